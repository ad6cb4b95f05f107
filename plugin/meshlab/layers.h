// Writing results into a MeshLab document as new layers.
#ifndef FILTER_COMPATMESH_LAYERS_H
#define FILTER_COMPATMESH_LAYERS_H

#include <common/meshmodel.h>

#include <cstdint>
#include <string>
#include <vector>

namespace compatmesh_plugin {

// A triangle mesh ready to become a layer.
struct LayerData {
  std::string label;
  std::vector<float> xyz;          // 3 * vertices
  std::vector<int32_t> triangles;  // 3 * faces
  std::vector<float> quality;      // per vertex, or empty for none
};

// Adds one new layer per entry (not made current), with normals and
// bounding boxes updated; vertex quality is enabled and filled when given.
// Layers with faces are marked polygonal (each triangle its own polygon),
// so the GUI draws their edges over the shading.
void add_layers(MeshDocument &md, const std::vector<LayerData> &layers);

}  // namespace compatmesh_plugin

#endif
