#include "filter_compatmesh.h"

#include "compatible_pair.h"
#include "default_layers.h"
#include "sweep.h"

#include <vector>

namespace {

const char *kCitation =
    "<br>V. Surazhsky and C. Gotsman, <b>High Quality Compatible Triangulations</b>, "
    "Proc. 11th International Meshing Roundtable (IMR) 2002; Engineering with Computers "
    "20(2):147-156, 2004.";

// The two layers named by FirstMesh and SecondMesh, or an error.
bool two_layers(const RichParameterList &par, MeshModel *&first, MeshModel *&second, QString &error)
{
  first = par.getMesh("FirstMesh");
  second = par.getMesh("SecondMesh");
  if (!first || !second) error = "a layer does not exist";
  else if (first == second) error = "FirstMesh and SecondMesh are the same layer; choose two layers";
  return error.isEmpty();
}

}  // namespace

FilterCompatMesh::FilterCompatMesh()
{
  typeList << FP_COMPATIBLE_TRIANGULATION << FP_COMPATIBLE_SWEEP;
  for (FilterIDType id : types()) actionList << new QAction(filterName(id), this);
}

QString FilterCompatMesh::pluginName() const { return "FilterCompatMesh"; }

// These names are how .mlx scripts call the filters: never change them.
QString FilterCompatMesh::filterName(FilterIDType filter) const
{
  switch (filter) {
    case FP_COMPATIBLE_TRIANGULATION: return "Compatible Triangulation of Two Boundaries";
    case FP_COMPATIBLE_SWEEP: return "Compatible Sweep Between Two Boundaries";
  }
  return "unknown";
}

QString FilterCompatMesh::filterInfo(FilterIDType filter) const
{
  switch (filter) {
    case FP_COMPATIBLE_TRIANGULATION:
      return QString("Triangulates the regions bounded by two planar closed boundaries with one "
                     "connectivity (compatible triangulations), adding as few interior Steiner "
                     "vertices as needed and remeshing for a large smallest angle. Each layer may "
                     "be a closed polyline (an edge mesh, e.g. from <i>Compute Planar Section</i>) "
                     "or a disk-like mesh (its boundary loop is used); the planes may differ. "
                     "Writes two new layers with identical faces; Steiner vertices have vertex "
                     "quality 1, boundary vertices 0. The result is checked with exact predicates "
                     "after rounding to float.") + kCitation;
    case FP_COMPATIBLE_SWEEP:
      return QString("Builds intermediate sections between two compatible layers (the output of "
                     "<i>Compatible Triangulation of Two Boundaries</i>) and the lateral surface "
                     "through their boundaries, as new layers. Every section is checked with exact "
                     "predicates after rounding to float (projected onto its best-fitting plane, no "
                     "triangle may flip and the boundary must stay simple); an invalid section is "
                     "reported and nothing is added.") + kCitation;
  }
  return "unknown";
}

MeshFilterInterface::FilterClass FilterCompatMesh::getClass(QAction *)
{
  return FilterClass(Layer + Remeshing);
}

void FilterCompatMesh::initParameterSet(QAction *action, MeshDocument &md, RichParameterList &par)
{
  // The second layer defaults to the first one that is not current.
  MeshModel *first = md.mm(), *other = md.mm();
  for (MeshModel *m : md.meshList)
    if (m != md.mm()) {
      other = m;
      break;
    }
  // The sweep defaults to the newest layer with faces and the newest older
  // one with as many vertices and faces: the pair the triangulation filter
  // has just added, in its order.
  if (ID(action) == FP_COMPATIBLE_SWEEP) {
    std::vector<MeshModel *> all(md.meshList.begin(), md.meshList.end());
    std::vector<compatmesh_plugin::LayerCounts> counts;
    for (MeshModel *m : all) counts.push_back({m->cm.vn, m->cm.fn});
    std::size_t i = 0, j = 0;
    if (compatmesh_plugin::newest_compatible_pair(counts, i, j)) first = all[i], other = all[j];
  }
  par.addParam(RichMesh("FirstMesh", first, &md, "First boundary", "Layer with the first closed boundary"));
  par.addParam(RichMesh("SecondMesh", other, &md, "Second boundary", "Layer with the second closed boundary"));
  switch (ID(action)) {
    case FP_COMPATIBLE_TRIANGULATION:
      par.addParam(RichFloat("MinAngle", 25.f, "Target smallest angle (deg)",
                             "Remeshing stops when every triangle of both layers reaches this angle "
                             "(at most half the corner angle at sharp boundary corners), in (0, 60)."));
      par.addParam(RichInt("MaxSteiner", -1, "Steiner budget",
                           "Most Steiner vertices the refinement may add; -1: automatic (2n + 100); "
                           "0: no refinement."));
      par.addParam(RichBool("Remesh", true, "Remesh",
                            "Improve angles by flips, smoothing and splits applied to both layers at once."));
      par.addParam(RichEnum("Correspondence", 2, QStringList() << "index" << "arc length" << "auto" << "similarity",
                            "Correspondence",
                            "Which boundary points correspond. index: vertex i of one layer is vertex i "
                            "of the other (equal counts, same direction). arc length: normalised arc "
                            "length between the pins (or from each boundary's first vertex). auto: "
                            "conformal, both boundaries mapped onto the disk and made to agree (where "
                            "turns fit alike, as a disc's, the one that puts holes on holes and turns "
                            "least), thin "
                            "parts' crowding tempered (with holes: the outer loops so, the holes paired "
                            "by position, each from the start and direction that align it best). "
                            "similarity: arc length from the start and direction that align the "
                            "boundaries best, for boundaries without holes too. With "
                            "arc length and auto the counts may differ: every input vertex is kept and "
                            "the other boundary's vertices are added on its edges."));
      par.addParam(RichString("Pins", "", "Pins",
                              "Vertices that must correspond, as 'I,J' pairs separated by ';' (vertex I "
                              "of the first layer with vertex J of the second, the layers' vertex "
                              "numbers), in the same order along both boundaries. Arc length and auto only."));
      par.addParam(RichFloat("MaxEdge", 0.f, "Largest boundary edge",
                             "0: off. Otherwise the boundary edges are split compatibly (the same number "
                             "of points on corresponding edges, every input vertex kept) until none is "
                             "longer than this in either layer: an element size along the boundary."));
      par.addParam(RichFloat("TimeLimit", 0.f, "Time limit (s)",
                             "0: none. Otherwise remeshing stops once the filter has used this many CPU "
                             "seconds and the result reached is kept (valid, checked as always; the "
                             "log says so). The stages before remeshing always run whole."));
      break;
    case FP_COMPATIBLE_SWEEP:
      par.addParam(RichInt("Sections", 5, "Sections", "Number of intermediate sections, at least 1."));
      par.addParam(RichSaveFile("VolumeFile", "", "*.msh", "Volume mesh (.msh)",
                                "Empty: none. Otherwise the volume between the layers in tetrahedra, every "
                                "one of positive volume (checked exactly), written as a Gmsh .msh file "
                                "(format 4.1) for finite-element solvers."));
      break;
  }
}

bool FilterCompatMesh::fail(const QString &message)
{
  // meshlabserver prints the log, not errorMessage: say it in both.
  Log(GLLogStream::FILTER, ("Error: " + message).toStdString());
  errorMessage = message;
  return false;
}

bool FilterCompatMesh::applyFilter(QAction *action, MeshDocument &md, const RichParameterList &par,
                                   vcg::CallBackPos *cb)
{
  MeshModel *first = nullptr, *second = nullptr;
  QString error;
  if (!two_layers(par, first, second, error)) return fail(error);
  const std::string first_name = first->label().toStdString(), second_name = second->label().toStdString();
  compatmesh_plugin::ThrottledProgress progress(cb);
  std::vector<compatmesh_plugin::LayerData> layers;
  std::vector<std::string> log;
  try {
    if (ID(action) == FP_COMPATIBLE_TRIANGULATION) {
      compatmesh_plugin::PairSettings settings;
      settings.min_angle_deg = par.getFloat("MinAngle");
      settings.max_steiner = par.getInt("MaxSteiner");
      settings.remesh = par.getBool("Remesh");
      const cm_correspondence modes[] = {CM_CORRESPOND_INDEX, CM_CORRESPOND_ARCLENGTH, CM_CORRESPOND_AUTO,
                                         CM_CORRESPOND_SIMILARITY};
      const int mode = par.getEnum("Correspondence");
      if (mode < 0 || mode > 3) return fail("Correspondence: unknown value " + QString::number(mode));
      settings.correspondence = modes[mode];
      settings.pins = par.getString("Pins").toStdString();
      settings.max_edge = par.getFloat("MaxEdge");
      if (!(settings.max_edge >= 0)) return fail("MaxEdge: expected 0 (off) or a positive length");
      settings.time_limit = par.getFloat("TimeLimit");
      if (!(settings.time_limit >= 0)) return fail("TimeLimit: expected 0 (none) or positive seconds");
      auto outcome = compatmesh_plugin::compatible_pair(first->cm, second->cm, first_name, second_name,
                                                        settings, progress);
      layers = std::move(outcome.layers);
      log = std::move(outcome.log);
    } else {
      auto outcome = compatmesh_plugin::compatible_sweep(first->cm, second->cm, first_name, second_name,
                                                         par.getInt("Sections"),
                                                         par.getSaveFileName("VolumeFile").toStdString(), progress);
      layers = std::move(outcome.layers);
      log = std::move(outcome.log);
    }
  } catch (const std::exception &e) {
    return fail(QString::fromStdString(e.what()));
  }
  compatmesh_plugin::add_layers(md, layers);
  for (const std::string &line : log) Log(GLLogStream::FILTER, line);
  return true;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterCompatMesh)
