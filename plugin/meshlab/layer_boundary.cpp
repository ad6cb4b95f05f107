#include "layer_boundary.h"

#include <algorithm>

namespace compatmesh_plugin {

namespace {

using OpenMesh::VertexHandle;

// Edges of a face-less layer, directed so that each closed loop is
// traversed one way (MeshLab's edges have no direction); several loops are
// a polygon with holes for the adapter. source_index names vertices in
// messages.
std::vector<std::pair<int, int>> directed_edges(const std::vector<std::pair<int, int>> &edges,
                                                std::size_t n_vertices,
                                                const std::vector<int> &source_index)
{
  std::vector<std::vector<int>> incident(n_vertices);
  for (std::size_t e = 0; e < edges.size(); e++) {
    if (edges[e].first == edges[e].second)
      throw compatmesh::Error(CM_ERR_ARGUMENT, "edge " + std::to_string(e) + " is a loop at vertex " +
                                                   std::to_string(source_index[edges[e].first]));
    incident[edges[e].first].push_back(int(e));
    incident[edges[e].second].push_back(int(e));
  }
  for (std::size_t v = 0; v < n_vertices; v++)
    if (!incident[v].empty() && incident[v].size() != 2)
      throw compatmesh::Error(
          CM_ERR_ARGUMENT, "the edges are not closed polylines: vertex " +
                               std::to_string(source_index[v]) + " has " +
                               (incident[v].size() == 1
                                    ? std::string("one edge (an open end)")
                                    : std::to_string(incident[v].size()) + " edges (a branch)"));

  std::vector<std::pair<int, int>> directed;
  std::vector<char> used(edges.size(), 0);
  for (std::size_t start = 0; start < edges.size(); start++) {
    if (used[start]) continue;
    int from = edges[start].first, e = int(start);
    while (!used[e]) {
      used[e] = 1;
      int to = edges[e].first == from ? edges[e].second : edges[e].first;
      directed.emplace_back(from, to);
      const std::vector<int> &next = incident[to];
      e = next[0] == e ? next[1] : next[0];
      from = to;
    }
  }
  return directed;
}

}  // namespace

compatmesh::PolyMesh layer_to_openmesh(const CMeshO &layer, std::vector<int> &source_index)
{
  compatmesh::PolyMesh mesh;
  std::vector<int> compact(layer.vert.size(), -1);
  source_index.clear();
  const bool identity = layer.Tr == Matrix44m::Identity();
  for (std::size_t i = 0; i < layer.vert.size(); i++) {
    const CVertexO &v = layer.vert[i];
    if (v.IsD()) continue;
    compact[i] = int(source_index.size());
    source_index.push_back(int(i));
    // Layers may carry a placement matrix; results are written in world
    // coordinates with none.
    const Point3m p = identity ? v.cP() : layer.Tr * v.cP();
    mesh.add_vertex(compatmesh::PolyMesh::Point(p[0], p[1], p[2]));
  }
  auto index_of = [&](const CVertexO *v) { return compact[v - &layer.vert[0]]; };

  for (std::size_t f = 0; f < layer.face.size(); f++) {
    const CFaceO &face = layer.face[f];
    if (face.IsD()) continue;
    std::vector<VertexHandle> corners;
    for (int k = 0; k < 3; k++) corners.push_back(VertexHandle(index_of(face.cV(k))));
    if (!mesh.add_face(corners).is_valid())
      throw compatmesh::Error(CM_ERR_ARGUMENT,
                              "face " + std::to_string(f) +
                                  " makes the mesh non-manifold or flips its orientation; need a disk");
  }
  if (mesh.n_faces() > 0) return mesh;

  std::vector<std::pair<int, int>> edges;
  for (std::size_t e = 0; e < layer.edge.size(); e++) {
    const CEdgeO &edge = layer.edge[e];
    if (edge.IsD()) continue;
    int a = index_of(edge.cV(0)), b = index_of(edge.cV(1));
    if (a < 0 || b < 0)
      throw compatmesh::Error(CM_ERR_ARGUMENT, "edge " + std::to_string(e) + " uses a deleted vertex");
    edges.emplace_back(a, b);
  }
  for (const auto &e : directed_edges(edges, mesh.n_vertices(), source_index))
    mesh.new_edge(VertexHandle(e.first), VertexHandle(e.second));
  return mesh;
}

compatmesh::Boundary layer_boundary(const CMeshO &layer, bool &is_disk)
{
  std::vector<int> source_index;
  compatmesh::PolyMesh mesh = layer_to_openmesh(layer, source_index);
  is_disk = mesh.n_faces() > 0;
  if (!is_disk && mesh.n_edges() == 0)
    throw compatmesh::Error(CM_ERR_ARGUMENT,
                            "the layer has neither faces nor edges; need a closed polyline or a disk");
  compatmesh::Boundary boundary = compatmesh::read_boundary(mesh);
  for (int &v : boundary.source_vertex) v = source_index[v];
  return boundary;
}

}  // namespace compatmesh_plugin
