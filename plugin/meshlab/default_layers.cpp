#include "default_layers.h"

namespace compatmesh_plugin {

bool newest_compatible_pair(const std::vector<LayerCounts> &layers, std::size_t &first, std::size_t &second)
{
  for (std::size_t i = layers.size(); i-- > 1;) {
    if (layers[i].faces == 0) continue;
    for (std::size_t j = i; j-- > 0;)
      if (layers[j].faces == layers[i].faces && layers[j].vertices == layers[i].vertices) {
        first = j, second = i;
        return true;
      }
  }
  return false;
}

}  // namespace compatmesh_plugin
