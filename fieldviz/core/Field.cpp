#include "fieldviz/core/Field.h"

#include <stdexcept>

namespace fluidviz {

namespace {
template <class F>
const F* findByName(const std::vector<F>& fields, const std::string& name) {
  for (const F& f : fields)
    if (f.name == name) return &f;
  return nullptr;
}

template <class F>
void checkFits(const Grid& grid, const F& f) {
  if (!grid.sameShape(f.grid))
    throw std::invalid_argument("field '" + f.name + "' is on grid " + f.grid.describe() +
                                ", the set is on " + grid.describe());
  if (f.values.size() != grid.nodeCount())
    throw std::invalid_argument("field '" + f.name + "' has " + std::to_string(f.values.size()) +
                                " values for " + std::to_string(grid.nodeCount()) + " nodes");
}
}  // namespace

const ScalarField* FieldSet::findScalar(const std::string& name) const {
  return findByName(scalars, name);
}
const VectorField* FieldSet::findVector(const std::string& name) const {
  return findByName(vectors, name);
}

void FieldSet::add(ScalarField f) {
  checkFits(grid, f);
  scalars.push_back(std::move(f));
}
void FieldSet::add(VectorField f) {
  checkFits(grid, f);
  vectors.push_back(std::move(f));
}

std::vector<std::string> FieldSet::arrayNames() const {
  std::vector<std::string> names;
  for (const auto& v : vectors) names.push_back(v.name);
  for (const auto& s : scalars) names.push_back(s.name);
  return names;
}

ScalarField magnitude(const VectorField& v, const std::string& name) {
  ScalarField s{name, v.grid, std::vector<double>(v.values.size())};
  for (std::size_t n = 0; n < v.values.size(); ++n) s.values[n] = v.values[n].norm();
  return s;
}

}  // namespace fluidviz
