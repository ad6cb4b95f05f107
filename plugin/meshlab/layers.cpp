#include "layers.h"

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>

namespace compatmesh_plugin {

void add_layers(MeshDocument &md, const std::vector<LayerData> &layers)
{
  for (const LayerData &data : layers) {
    MeshModel *mm = md.addNewMesh("", QString::fromStdString(data.label), false);
    CMeshO &m = mm->cm;
    const std::size_t nv = data.xyz.size() / 3, nf = data.triangles.size() / 3;
    if (!data.quality.empty()) mm->updateDataMask(MeshModel::MM_VERTQUALITY);
    // A filter cannot choose how the GUI draws a new layer: MeshLab picks
    // that from the layer (suggestedDefaultPerViewRenderingData). A
    // polygonal layer is drawn flat shaded with its edges over it, and ours
    // is one, whose polygons are the triangles (no edge is faux): without
    // the edges a compatible pair shows as two flat grey disks.
    if (!data.triangles.empty()) mm->updateDataMask(MeshModel::MM_POLYGONAL);
    vcg::tri::Allocator<CMeshO>::AddVertices(m, nv);
    for (std::size_t i = 0; i < nv; i++) {
      m.vert[i].P() = Point3m(data.xyz[3 * i], data.xyz[3 * i + 1], data.xyz[3 * i + 2]);
      if (!data.quality.empty()) m.vert[i].Q() = data.quality[i];
    }
    vcg::tri::Allocator<CMeshO>::AddFaces(m, nf);
    for (std::size_t f = 0; f < nf; f++)
      for (int k = 0; k < 3; k++) m.face[f].V(k) = &m.vert[data.triangles[3 * f + k]];
    vcg::tri::UpdateBounding<CMeshO>::Box(m);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFaceNormalized(m);
  }
}

}  // namespace compatmesh_plugin
