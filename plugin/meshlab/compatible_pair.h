// "Compatible Triangulation of Two Boundaries": the worker behind the
// filter. Reads the two layers' polygons, runs the core with the chosen
// correspondence, and returns the two output layers after checking them
// as floats. Changes no layer.
#ifndef FILTER_COMPATMESH_COMPATIBLE_PAIR_H
#define FILTER_COMPATMESH_COMPATIBLE_PAIR_H

#include "filter_error.h"
#include "layers.h"
#include "progress.h"

#include <compatmesh/compatmesh.h>
#include <common/ml_mesh_type.h>

#include <string>
#include <vector>

namespace compatmesh_plugin {

struct PairSettings {
  double min_angle_deg = 25;
  long max_steiner = -1;
  bool remesh = true;
  cm_correspondence correspondence = CM_CORRESPOND_AUTO;
  // "I,J; I,J ...": vertex I of the first layer tied to vertex J of the
  // second (the layers' own vertex numbers); empty: none.
  std::string pins;
  double max_edge = 0;  // > 0: boundary edges split to at most this length
  double time_limit = 0;  // > 0: CPU seconds after which remeshing stops (cm_options.time_limit)
};

struct PairOutcome {
  std::vector<LayerData> layers;  // two, identical triangles
  std::vector<std::string> log;   // lines for MeshLab's log
};

// first, second: the layers; names: their labels (for messages and the new
// layers' labels). Throws FilterError with a one-line message.
PairOutcome compatible_pair(const CMeshO &first, const CMeshO &second,
                            const std::string &first_name, const std::string &second_name,
                            const PairSettings &settings, ThrottledProgress &progress);

}  // namespace compatmesh_plugin

#endif
