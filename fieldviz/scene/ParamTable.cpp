#include "fieldviz/scene/ParamTable.h"

namespace fluidviz::scene {

const ParamRow* findParamRow(const std::vector<ParamRow>& rows, const std::string& key) {
  for (const ParamRow& row : rows)
    if (row.key == key) return &row;
  return nullptr;
}

}  // namespace fluidviz::scene
