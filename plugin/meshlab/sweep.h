// "Compatible Sweep Between Two Boundaries": the worker behind the filter.
// Takes two layers with one connectivity (the output of the pairing
// filter), builds intermediate sections and the lateral surface through
// their boundaries, and checks every section exactly after float rounding:
// projected onto its best-fitting plane, every triangle keeps its
// orientation and the boundary stays simple (so the section is an embedded
// disk, also when the end planes are not parallel and sections bend).
#ifndef FILTER_COMPATMESH_SWEEP_H
#define FILTER_COMPATMESH_SWEEP_H

#include "filter_error.h"
#include "layers.h"
#include "progress.h"

#include <common/ml_mesh_type.h>

#include <string>
#include <vector>

namespace compatmesh_plugin {

// The section at time t in [0, 1] between the two compatible geometries
// (3 * vertices doubles each): the one place that decides how sections are
// made. Linear interpolation of the vertices.
std::vector<double> section_at(const std::vector<double> &start, const std::vector<double> &end,
                               double t);

struct SweepOutcome {
  std::vector<LayerData> layers;  // the sections, then the lateral surface
  std::vector<std::string> log;
};

// sections: intermediate sections, >= 1. Throws FilterError.
SweepOutcome compatible_sweep(const CMeshO &first, const CMeshO &second,
                              const std::string &first_name, const std::string &second_name,
                              int sections, ThrottledProgress &progress);

}  // namespace compatmesh_plugin

#endif
