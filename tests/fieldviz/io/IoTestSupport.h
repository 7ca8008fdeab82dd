#pragma once
// Helpers shared by the I/O tests: a fresh folder per test, a listing of it, and a vtkOutputWindow
// that counts what VTK would have printed (bad input must raise exceptions, not print).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkOutputWindow.h>
#include <vtkSmartPointer.h>
#include "tests/support/TextFiles.h"

namespace fluidviz::testing {

/// `text` holds `piece`; the failure message shows both.
inline ::testing::AssertionResult contains(const std::string& text, const std::string& piece) {
  if (text.find(piece) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << piece << "\"";
}

class TestFolder {
 public:
  TestFolder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = "fluidviz_io_" + std::string(info->test_suite_name()) + "_" + info->name() +
                       "_" + std::to_string(::getpid());
    std::replace(name.begin(), name.end(), '/', '_');  // parameterised names contain '/'
    path_ = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TestFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

  /// Names of everything in the folder (temporary files included: they start with '.').
  std::set<std::string> names() const {
    std::set<std::string> out;
    for (const auto& e : std::filesystem::directory_iterator(path_))
      out.insert(e.path().filename().string());
    return out;
  }

 private:
  std::filesystem::path path_;
};


/// Counts every message VTK sends to its output window while installed.
class CountingOutputWindow : public vtkOutputWindow {
 public:
  static CountingOutputWindow* New() {
    auto* window = new CountingOutputWindow;
    window->InitializeObjectBase();
    return window;
  }
  vtkTypeMacro(CountingOutputWindow, vtkOutputWindow);
  void DisplayText(const char* text) override {
    ++count;
    last = text ? text : "";
  }
  int count = 0;
  std::string last;
};

/// Installs a CountingOutputWindow for its lifetime.
class VtkOutputCounter {
 public:
  VtkOutputCounter() : window_(vtkSmartPointer<CountingOutputWindow>::New()) {
    previous_ = vtkOutputWindow::GetInstance();
    vtkOutputWindow::SetInstance(window_);
  }
  ~VtkOutputCounter() { vtkOutputWindow::SetInstance(previous_); }
  int count() const { return window_->count; }
  const std::string& last() const { return window_->last; }

 private:
  vtkSmartPointer<CountingOutputWindow> window_;
  vtkSmartPointer<vtkOutputWindow> previous_;
};

}  // namespace fluidviz::testing
