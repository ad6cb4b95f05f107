// Which layers a filter's dialog offers first. Kept free of MeshLab types
// so the choice is tested on its own (tests/meshlab/test_default_layers.cpp).
#ifndef COMPATMESH_PLUGIN_DEFAULT_LAYERS_H
#define COMPATMESH_PLUGIN_DEFAULT_LAYERS_H

#include <cstddef>
#include <utility>
#include <vector>

namespace compatmesh_plugin {

struct LayerCounts {
  int vertices, faces;
};

// The sweep's two layers, oldest first, given every layer's counts in the
// document's order (newest last): the newest layer with faces and the
// newest older one with as many vertices and faces (the pair the
// triangulation filter has just added, in its order). False if none.
bool newest_compatible_pair(const std::vector<LayerCounts> &layers, std::size_t &first, std::size_t &second);

}  // namespace compatmesh_plugin

#endif
