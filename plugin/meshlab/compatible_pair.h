// "Compatible Triangulation of Two Boundaries": the worker behind the
// filter. Reads the two layers' polygons, pairs their vertices (start
// offset, direction, common count), runs the core, and returns the two
// output layers after checking them as floats. Changes no layer.
#ifndef FILTER_COMPATMESH_COMPATIBLE_PAIR_H
#define FILTER_COMPATMESH_COMPATIBLE_PAIR_H

#include "filter_error.h"
#include "layers.h"
#include "progress.h"

#include <common/ml_mesh_type.h>

#include <string>
#include <vector>

namespace compatmesh_plugin {

struct PairSettings {
  double min_angle_deg = 25;
  long max_steiner = -1;
  bool remesh = true;
  int start_offset = 0;         // vertex of the second boundary paired with the first's vertex 0
  bool reverse_second = false;  // walk the second boundary the other way
  bool resample = true;         // bring different counts to a common one by arc length
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
