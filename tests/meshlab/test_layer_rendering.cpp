// How the MeshLab GUI first draws a layer the filters add: MeshLab's own
// policy (libmeshlab-common's suggestedDefaultPerViewRenderingData, which
// the main window calls for every new layer, with its default of 50000
// faces for smooth shading) must give flat shading with every edge drawn
// over it, not a flat grey disk.
#include "layers.h"

#include <common/ml_shared_data_context.h>

#include <cstdio>

static int failures = 0;

static void expect(bool condition, const char *what)
{
  if (!condition) {
    std::printf("FAILED %s\n", what);
    failures++;
  }
}

int main()
{
  MeshDocument md;
  compatmesh_plugin::LayerData square;
  square.label = "pair";
  square.xyz = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5f, 0.5f, 0};
  square.triangles = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
  square.quality = {0, 0, 0, 0, 1};
  compatmesh_plugin::add_layers(md, {square});
  MeshModel *layer = md.meshList.back();
  expect(layer->cm.FN() == 4 && layer->cm.VN() == 5, "the layer has the faces and vertices given");

  MLRenderingData shown;
  MLPoliciesStandAloneFunctions::suggestedDefaultPerViewRenderingData(layer, shown, 50000);
  expect(shown.isPrimitiveActive(MLRenderingData::PR_SOLID), "the faces are shaded");
  expect(shown.isPrimitiveActive(MLRenderingData::PR_WIREFRAME_EDGES), "every edge is drawn over them");
  MLRenderingData::RendAtts solid;
  shown.get(MLRenderingData::PR_SOLID, solid);
  expect(solid[MLRenderingData::ATT_NAMES::ATT_FACENORMAL], "flat shading (per-face normals)");
  // No edge is faux: the wireframe of a polygonal layer skips faux edges.
  for (const CFaceO &f : layer->cm.face)
    for (int k = 0; k < 3; k++) expect(!f.IsF(k), "no faux edge");

  std::printf("test_layer_rendering: %d failed\n", failures);
  return failures ? 1 : 0;
}
