// The bad-input matrix (tests/bad_input/cases.txt) through the OpenMesh
// adapter, each polygon a face-less mesh of its vertices in order (what
// OpenMesh reads from an OBJ polyline) in the plane z = 0: the core's
// status and location come through compatmesh::Error, the message is one
// line, and the legal cases give one triangle mesh per input with the input
// vertices first, unchanged.
#include "helpers.hh"

#include "bad_input_cases.h"

static void run_case(const bic_case &c)
{
  std::vector<PolyMesh> inputs;
  for (size_t g = 0; g < c.k; g++) {
    Points points;
    for (size_t i = 0; i < c.counts[g]; i++) points.push_back({{c.xy[g][2 * i], c.xy[g][2 * i + 1], 0.0}});
    inputs.push_back(vertex_mesh(points));
  }
  cm_options index;  // the matrix states the index correspondence's contract (equal counts)
  cm_options_init(&index);
  try {
    std::vector<TriMesh> outputs = compatmesh::compatible_triangulation(inputs, &index);
    CHECK_MSG(c.status == CM_OK, "%s: succeeded, want %s", c.name, cm_status_string(c.status));
    CHECK_MSG(outputs.size() == c.k, "%s: %zu outputs", c.name, outputs.size());
    for (size_t g = 0; g < outputs.size(); g++) {
      int changed = 0;
      for (size_t i = 0; i < c.counts[g]; i++) {
        auto p = outputs[g].point(OpenMesh::VertexHandle(int(i)));
        changed += p[0] != c.xy[g][2 * i] || p[1] != c.xy[g][2 * i + 1] || p[2] != 0.0;
      }
      CHECK_MSG(changed == 0 && outputs[g].n_faces() > 0, "%s: output %zu has %d changed vertices", c.name, g,
                changed);
    }
  } catch (const compatmesh::Error &e) {
    std::string message = e.what();
    CHECK_MSG(e.status() == c.status, "%s: got %s (%s), want %s", c.name, cm_status_string(e.status()),
              e.what(), cm_status_string(c.status));
    CHECK_MSG(!message.empty() && message.find('\n') == std::string::npos, "%s: message '%s'", c.name,
              e.what());
    CHECK_MSG((c.polygon == BIC_NOT_CHECKED || e.mesh() == c.polygon) &&
                  (c.vertex == BIC_NOT_CHECKED || e.vertex() == c.vertex),
              "%s: location (%ld, %ld), want (%ld, %ld)", c.name, e.mesh(), e.vertex(), c.polygon, c.vertex);
  }
}

int main(int argc, char **argv)
{
  bic_case *cases;
  size_t count;
  if (bic_load(argc > 1 ? argv[1] : "tests/bad_input/cases.txt", &cases, &count) != 0) return 1;
  for (size_t i = 0; i < count; i++) run_case(cases[i]);
  bic_free(cases, count);
  return check_summary("test_input_matrix (OpenMesh)");
}
