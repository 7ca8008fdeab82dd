// The proxies' XML (ServerManagerXml.h) against the declarations it is written from: every key
// of LicParams, TopologyParams, the streamline and the resample parameters is one property (two for an optional number) with the key's
// default, range and text, parsed back with VTK's XML parser (the test sits above every layer).
#include "paraview/properties/ServerManagerXml.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>

#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLUtilities.h>

#include "paraview/properties/FluidvizProxies.h"

using namespace fluidviz;
namespace pv = fluidviz::paraview;

namespace {

struct ParsedXml {
  vtkSmartPointer<vtkXMLDataElement> element;
  explicit ParsedXml(const std::string& text) {
    element.TakeReference(vtkXMLUtilities::ReadElementFromString(text.c_str()));
    EXPECT_NE(element, nullptr) << text.substr(0, 400);
  }
  vtkXMLDataElement* root() { return element; }
};

std::map<std::string, vtkXMLDataElement*> propertiesOf(vtkXMLDataElement* proxy) {
  std::map<std::string, vtkXMLDataElement*> byName;
  for (int i = 0; i < proxy->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* e = proxy->GetNestedElement(i);
    if (const char* name = e->GetAttribute("name")) byName[name] = e;
  }
  return byName;
}

vtkXMLDataElement* proxyNamed(vtkXMLDataElement* root, const std::string& name) {
  for (int g = 0; g < root->GetNumberOfNestedElements(); ++g) {
    vtkXMLDataElement* group = root->GetNestedElement(g);
    for (int i = 0; i < group->GetNumberOfNestedElements(); ++i)
      if (group->GetNestedElement(i)->GetAttribute("name") == name)
        return group->GetNestedElement(i);
  }
  return nullptr;
}

TEST(ServerManagerXml, PropertyNamesAreTheKeysInCamelCase) {
  EXPECT_EQ(pv::propertyName("length"), "Length");
  EXPECT_EQ(pv::propertyName("contrast_sigmas"), "ContrastSigmas");
  EXPECT_EQ(pv::propertyName("separatrix_integration.max_step"), "SeparatrixIntegrationMaxStep");
}

// The declaration drives the property: for each row, kind -> element type and command, the
// default value, the range domain and the documentation's unit, range and scene key.
TEST(ServerManagerXml, EveryDeclaredKeyIsOnePropertyWithItsDefaultAndRange) {
  const std::vector<pv::ProxyDescription> proxies = pv::fluidvizProxies();
  ParsedXml xml(pv::serverManagerXml(proxies));
  ASSERT_NE(xml.root(), nullptr);
  int checked = 0;
  for (const pv::ProxyDescription& proxy : proxies) {
    vtkXMLDataElement* element = proxyNamed(xml.root(), proxy.name);
    ASSERT_NE(element, nullptr) << proxy.name;
    EXPECT_STREQ(element->GetAttribute("class"), proxy.vtkClass.c_str());
    const auto properties = propertiesOf(element);
    for (const scene::ParamRow& row : proxy.params) {
      if (row.kind == scene::ParamKind::list) continue;
      const std::string name = pv::propertyName(row.key);
      ASSERT_TRUE(properties.count(name)) << proxy.name << ": no property " << name;
      vtkXMLDataElement* p = properties.at(name);
      EXPECT_STREQ(p->GetAttribute("initial_string"), row.key.c_str());
      // paraview.simple names a property after its label without spaces.
      std::string label = p->GetAttribute("label");
      label.erase(std::remove(label.begin(), label.end(), ' '), label.end());
      EXPECT_EQ(label, name);
      // An empty text default (resample's arrays: all) has no attribute value once parsed.
      const char* given = p->GetAttribute("default_values");
      const std::string defaults = given ? given : "";
      switch (row.kind) {
        case scene::ParamKind::number:
          EXPECT_STREQ(p->GetName(), "DoubleVectorProperty");
          EXPECT_EQ(std::strtod(defaults.c_str(), nullptr), row.defaultValue.get<double>())
              << name;
          break;
        case scene::ParamKind::integer:
          EXPECT_STREQ(p->GetName(), "IntVectorProperty");
          EXPECT_EQ(std::stoi(defaults), row.defaultValue.get<int>()) << name;
          break;
        case scene::ParamKind::flag:
          EXPECT_EQ(defaults, row.defaultValue.get<bool>() ? "1" : "0") << name;
          break;
        case scene::ParamKind::choice: {
          const int index = std::stoi(defaults);
          ASSERT_LT(index, int(row.info.choices.size()));
          EXPECT_EQ(row.info.choices[index], row.defaultValue.get<std::string>()) << name;
          EXPECT_EQ(p->FindNestedElementWithName("EnumerationDomain")->GetNumberOfNestedElements(),
                    int(row.info.choices.size()));
          break;
        }
        case scene::ParamKind::numbers: {
          EXPECT_STREQ(p->GetName(), "DoubleVectorProperty");
          const int n = int(row.defaultValue.size());
          EXPECT_EQ(std::atoi(p->GetAttribute("number_of_elements")), n) << name;
          EXPECT_EQ(p->GetAttribute("command"), pv::numbersCommand(n)) << name;
          char* end = nullptr;
          const char* text = defaults.c_str();
          for (int i = 0; i < n; ++i, text = end)
            EXPECT_EQ(std::strtod(text, &end), row.defaultValue[i].get<double>()) << name;
          break;
        }
        case scene::ParamKind::optional_number:
          ASSERT_TRUE(properties.count(name + "Given")) << name;
          EXPECT_STREQ(properties.at(name + "Given")->GetAttribute("default_values"),
                       row.defaultValue.is_null() ? "0" : "1");
          break;
        default:
          break;
      }
      if (std::isfinite(row.info.min) || std::isfinite(row.info.max)) {
        vtkXMLDataElement* range = p->FindNestedElementWithName(
            row.kind == scene::ParamKind::integer ? "IntRangeDomain" : "DoubleRangeDomain");
        ASSERT_NE(range, nullptr) << name;
        if (std::isfinite(row.info.min)) {
          EXPECT_EQ(std::strtod(range->GetAttribute("min"), nullptr), row.info.min) << name;
        }
        if (std::isfinite(row.info.max)) {
          EXPECT_EQ(std::strtod(range->GetAttribute("max"), nullptr), row.info.max) << name;
        }
      }
      const std::string doc = p->FindNestedElementWithName("Documentation")->GetCharacterData();
      EXPECT_EQ(doc.find(row.info.description), 0u) << name;
      const std::string key = proxy.sceneSection.empty()
                                   ? "Key: " + row.key
                                   : "Scene key: " + proxy.sceneSection + "." + row.key;
      EXPECT_NE(doc.find(key), std::string::npos) << doc;
      if (!row.info.unit.empty()) {
        EXPECT_NE(doc.find("Unit: " + row.info.unit), std::string::npos) << doc;
      }
      ++checked;
    }
  }
  // LicParams has 17 keys, TopologyParams 16 of its own and 11 of separatrix_integration.
  EXPECT_GE(checked, 40);
}

TEST(ServerManagerXml, TextIsEscaped) {
  pv::ProxyDescription p{.name = "P", .label = "a < b & \"c\"", .vtkClass = "vtkP", .help = "x > y"};
  const std::string xml = pv::serverManagerXml({p});
  EXPECT_NE(xml.find("label=\"a &lt; b &amp; &quot;c&quot;\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("x &gt; y"), std::string::npos) << xml;
  ParsedXml parsed(xml);
  EXPECT_STREQ(proxyNamed(parsed.root(), "P")->GetAttribute("label"), "a < b & \"c\"");
}

}  // namespace
