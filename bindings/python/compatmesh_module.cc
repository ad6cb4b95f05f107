// Python module compatmesh: numpy arrays in, numpy arrays out, the core in
// between. Only translation lives here.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <compatmesh/compatmesh.h>
#include <compatmesh/handles.hh>
#include <compatmesh/plane.hh>
#include <abaqus_sets.h>
#ifdef CM_PYTHON_HAVE_GMSH
#include <gmsh_volume.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>
#endif

#include <algorithm>
#include <array>
#include <cerrno>
#include <cfloat>
#include <cstdio>
#include <cmath>
#include <limits>
#include <cstring>
#include <exception>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace {

using compatmesh::MorphPtr;
using compatmesh::ProgressRelay;
using compatmesh::ResultPtr;
using compatmesh::SweepPtr;

// One input polygon as the core sees it (xy), and how to map vertices back.
struct Polygon {
  std::vector<double> xy;   // 2n
  bool spatial = false;     // given as n x 3
  std::vector<double> xyz;  // 3n, the input, when spatial
  compatmesh::PlaneFrame frame;
  // With holes: the loops' sizes (outer first), the loops one after
  // another in xy; empty for one loop.
  std::vector<std::size_t> loop_sizes;
  std::size_t size() const { return xy.size() / 2; }
};

using FloatArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

// Limits that keep one call's output within reason (the command line's).
constexpr long kMaxFrames = 1000;

std::string shape_of(const py::array &a)
{
  std::string s = "(";
  for (py::ssize_t d = 0; d < a.ndim(); d++) s += (d ? ", " : "") + std::to_string(a.shape(d));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

[[noreturn]] void raise_input_error(const std::string &message, cm_status status, long polygon,
                                   long vertex, long other);

// object as an array of doubles, or a TypeError naming `what`: complex
// values are refused rather than cut to their real parts.
FloatArray real_array(py::handle object, const std::string &what)
{
  py::array any = py::array::ensure(object);
  if (!any) PyErr_Clear();
  if (any && any.dtype().kind() == 'c')
    throw py::type_error(what + ": complex values are not coordinates");
  FloatArray a = FloatArray::ensure(object);
  if (!a) {
    PyErr_Clear();
    throw py::type_error(what + ": not convertible to an array of floats");
  }
  return a;
}

// A polygon given as a list or tuple of loops (n x 2 arrays, the outer loop
// first): its first item is two-dimensional, where a list of points has
// points (one-dimensional) as items.
bool is_loop_list(py::handle object)
{
  if (!py::isinstance<py::list>(object) && !py::isinstance<py::tuple>(object)) return false;
  py::sequence items = py::reinterpret_borrow<py::sequence>(object);
  if (py::len(items) == 0) return false;
  py::object first = items[0];
  if (py::isinstance<py::array>(first)) return py::array(first).ndim() == 2;
  if (!py::isinstance<py::list>(first) && !py::isinstance<py::tuple>(first)) return false;
  py::sequence inner = py::reinterpret_borrow<py::sequence>(first);
  if (py::len(inner) == 0) return false;
  py::object point = inner[0];
  return py::isinstance<py::list>(point) || py::isinstance<py::tuple>(point) || py::isinstance<py::array>(point);
}

Polygon read_loops(py::handle object, std::size_t index)
{
  Polygon polygon;
  std::size_t l = 0;
  for (py::handle item : object) {
    std::string name = "polygon " + std::to_string(index) + ", loop " + std::to_string(l++);
    FloatArray a = real_array(item, name);
    if (a.ndim() != 2 || a.shape(1) != 2)
      throw py::value_error(name + ": expected an n x 2 array (loops of a polygon with holes are planar), got shape " +
                            shape_of(a));
    polygon.xy.insert(polygon.xy.end(), a.data(), a.data() + 2 * a.shape(0));
    polygon.loop_sizes.push_back(std::size_t(a.shape(0)));
  }
  return polygon;
}

// The GeoJSON geometry (RFC 7946) an object stands for: its
// __geo_interface__ (shapely, geopandas, fiona, pyshp give one), a mapping
// with "type" itself, or None where it is neither.
py::object geo_geometry(py::handle object)
{
  if (py::hasattr(object, "__geo_interface__")) return object.attr("__geo_interface__");
  if (py::isinstance<py::dict>(object) && object.contains("type")) return py::reinterpret_borrow<py::object>(object);
  return py::none();
}

// A GeoJSON Polygon's rings as the loops of a polygon (one ring: an n x 2 or
// n x 3 array; several: a list of n_j x 2 arrays, the exterior first). Its
// rings are closed (the last position repeats the first): the repeat is
// left out. A Feature gives its geometry, a FeatureCollection its one
// Feature's; any other type is an error.
py::object geo_loops(py::object geometry, std::size_t index)
{
  std::string name = "polygon " + std::to_string(index);
  auto member = [&](const char *key) {
    if (!py::isinstance<py::dict>(geometry) || !geometry.contains(key))
      throw py::value_error(name + ": a GeoJSON object without \"" + key + "\"");
    return py::object(geometry[key]);
  };
  std::string type = py::str(member("type"));
  if (type == "FeatureCollection") {
    py::object features = member("features");
    if (py::len(features) != 1)
      throw py::value_error(name + ": a FeatureCollection of " + std::to_string(py::len(features)) +
                            " features; expected exactly one (a Polygon)");
    return geo_loops(features[py::int_(0)], index);
  }
  if (type == "Feature") {
    py::object inner = member("geometry");
    if (inner.is_none()) throw py::value_error(name + ": a Feature without a geometry; expected a Polygon");
    return geo_loops(inner, index);
  }
  if (type != "Polygon")
    throw py::value_error(name + ": a GeoJSON " + type + "; expected a Polygon" +
                          (type == "MultiPolygon" ? " (give a MultiPolygon's parts one by one)" : ""));
  py::list loops;
  std::size_t l = 0;
  for (py::handle ring : member("coordinates")) {
    FloatArray a = real_array(ring, name + ", ring " + std::to_string(l++));
    py::ssize_t n = a.ndim() == 2 ? a.shape(0) : 0, columns = a.ndim() == 2 ? a.shape(1) : 0;
    bool closed = n > 1;
    for (py::ssize_t c = 0; closed && c < columns; c++) closed = *a.data(0, c) == *a.data(n - 1, c);
    loops.append(closed ? py::object(a[py::slice(0, n - 1, 1)]) : py::object(a));
  }
  if (loops.empty()) throw py::value_error(name + ": an empty GeoJSON Polygon");
  return loops.size() == 1 ? py::object(loops[0]) : py::object(loops);
}

Polygon read_polygon(py::handle object, std::size_t index, double tolerance,
                     compatmesh::NormalSign sign = compatmesh::NormalSign::Canonical)
{
  py::object geometry = geo_geometry(object);
  if (!geometry.is_none()) return read_polygon(geo_loops(geometry, index), index, tolerance, sign);
  if (is_loop_list(object)) return read_loops(object, index);
  std::string name = "polygon " + std::to_string(index);
  FloatArray a = real_array(object, name);
  if (a.ndim() != 2 || (a.shape(1) != 2 && a.shape(1) != 3))
    throw py::value_error(name + ": expected an n x 2 or n x 3 array, got shape " + shape_of(a));
  Polygon polygon;
  std::size_t n = std::size_t(a.shape(0));
  const double *data = a.data();
  if (a.shape(1) == 2) {
    polygon.xy.assign(data, data + 2 * n);
    return polygon;
  }
  polygon.spatial = true;
  polygon.xyz.assign(data, data + 3 * n);
  try {
    // Canonical sign: the winding reaches the core as given, as for n x 2;
    // a loft's sections follow their winding (sweep()).
    polygon.frame = compatmesh::fit_plane(data, n, tolerance, sign);
  } catch (const compatmesh::PlaneError &e) {
    // The same InputError the core's own checks give, located.
    raise_input_error(name + ": " + e.what(),
                      e.not_finite() ? CM_ERR_NOT_FINITE : CM_ERR_ARGUMENT, long(index),
                      long(e.vertex()), -1);
  }
  polygon.xy = compatmesh::to_plane(polygon.frame, data, n);
  return polygon;
}

// --- options -------------------------------------------------------------
// Keyword arguments map by name to the fields of cm_options; defaults come
// from cm_options_init. A new field needs one line in option_setters().

struct Callbacks {
  py::object progress;  // None or a callable
  bool correspondence_given = false;
  std::vector<std::vector<long>> pins;  // as given; checked against k later
  std::vector<std::size_t> pin_data;    // pins flattened, k per pin
};

using Setter = void (*)(cm_options &, py::handle, Callbacks &);

// An enum option: a name, or an int / compatmesh enum value (the core
// checks the range).
template <class Enum>
Enum enum_from(py::handle value, const char *option,
               const std::vector<std::pair<const char *, Enum>> &names)
{
  if (py::isinstance<py::str>(value)) {
    std::string name = value.cast<std::string>();
    for (const auto &entry : names)
      if (name == entry.first) return entry.second;
    std::string known;
    for (const auto &entry : names) known += std::string(known.empty() ? "" : ", ") + "'" + entry.first + "'";
    throw py::value_error("unknown " + std::string(option) + " '" + name + "' (known: " + known + ")");
  }
  try {
    return Enum(value.cast<int>());
  } catch (const py::cast_error &) {
    throw py::type_error(std::string(option) + " must be a name, an int or a compatmesh enum value");
  }
}

const std::vector<std::pair<const char *, cm_method>> method_names = {
    {"overlay", CM_METHOD_OVERLAY}, {"partition", CM_METHOD_PARTITION}};
const std::vector<std::pair<const char *, cm_correspondence>> correspondence_names = {
    {"index", CM_CORRESPOND_INDEX}, {"arclength", CM_CORRESPOND_ARCLENGTH}, {"auto", CM_CORRESPOND_AUTO},
    {"similarity", CM_CORRESPOND_SIMILARITY}};
const std::vector<std::pair<const char *, cm_smoothing>> smoothing_names = {
    {"laplacian", CM_SMOOTH_LAPLACIAN},
    {"angle", CM_SMOOTH_ANGLE},
    {"weighted", CM_SMOOTH_WEIGHTED},
    {"combined", CM_SMOOTH_COMBINED}};
const std::vector<std::pair<const char *, cm_remesher>> remesher_names = {
    {"greedy", CM_REMESHER_GREEDY}, {"map", CM_REMESHER_MAP}};

[[noreturn]] void raise_overflow(const std::string &message)
{
  PyErr_SetString(PyExc_OverflowError, message.c_str());
  throw py::error_already_set();
}

// A numeric option, as strict as the C API: an int where the field is an
// int (OverflowError when it does not fit, ValueError when negative for an
// unsigned field), a finite number where it is a double (ValueError for
// NaN and infinities). The core checks the range.
template <class T>
T number_from(py::handle value, const char *option)
{
  bool is_number = py::isinstance<py::int_>(value) || (std::is_floating_point<T>::value && py::isinstance<py::float_>(value));
  if (!is_number)
    throw py::type_error(std::string(option) + " must be " +
                         (std::is_floating_point<T>::value ? "a number" : "an int") + ", not " +
                         std::string(py::str(value.get_type().attr("__name__"))));
  if constexpr (std::is_floating_point<T>::value) {
    double x = value.cast<double>();
    if (!std::isfinite(x)) throw py::value_error(std::string(option) + " must be finite, got " + std::string(py::repr(value)));
    return T(x);
  } else {
    int overflow = 0;
    long long x = PyLong_AsLongLongAndOverflow(value.ptr(), &overflow);
    if (overflow > 0 || (overflow == 0 && x > 0 && static_cast<unsigned long long>(x) > std::numeric_limits<T>::max()))
      raise_overflow(std::string(option) + " = " + std::string(py::repr(value)) + " is too large");
    if (std::is_unsigned<T>::value && (overflow < 0 || x < 0))
      throw py::value_error(std::string(option) + " must not be negative, got " + std::string(py::repr(value)));
    if (overflow < 0 || x < static_cast<long long>(std::numeric_limits<T>::min()))
      raise_overflow(std::string(option) + " = " + std::string(py::repr(value)) + " is too small");
    return T(x);
  }
}

struct OptionSetter {
  const char *name;
  Setter set;
};

#define CM_NUMBER_OPTION(field)                                                 \
  {                                                                             \
    #field, [](cm_options &o, py::handle v, Callbacks &) {                      \
      o.field = number_from<decltype(o.field)>(v, #field);                      \
    }                                                                           \
  }

const std::vector<OptionSetter> &option_setters()
{
  static const std::vector<OptionSetter> setters = {
      {"method", [](cm_options &o, py::handle v, Callbacks &) { o.method = enum_from(v, "method", method_names); }},
      {"progress",
       [](cm_options &, py::handle v, Callbacks &c) {
         if (!v.is_none() && !PyCallable_Check(v.ptr()))
           throw py::type_error("progress must be callable(fraction, stage) or None");
         c.progress = py::reinterpret_borrow<py::object>(v);
       }},
      {"progress_user",
       [](cm_options &, py::handle, Callbacks &) {
         throw py::type_error("progress_user is not used from Python: give progress a closure");
       }},
      CM_NUMBER_OPTION(remesh),
      CM_NUMBER_OPTION(min_angle_deg),
      CM_NUMBER_OPTION(max_steiner),
      CM_NUMBER_OPTION(k_split),
      CM_NUMBER_OPTION(area_every),
      {"smoothing",
       [](cm_options &o, py::handle v, Callbacks &) { o.smoothing = enum_from(v, "smoothing", smoothing_names); }},
      {"remesher",
       [](cm_options &o, py::handle v, Callbacks &) { o.remesher = enum_from(v, "remesher", remesher_names); }},
      CM_NUMBER_OPTION(max_iterations),
      CM_NUMBER_OPTION(restarts),
      CM_NUMBER_OPTION(ceiling),
      {"correspondence",
       [](cm_options &o, py::handle v, Callbacks &c) {
         o.correspondence = enum_from(v, "correspondence", correspondence_names);
         c.correspondence_given = true;
       }},
      {"pins",
       [](cm_options &, py::handle v, Callbacks &c) {
         if (v.is_none()) return;
         if (!py::isinstance<py::sequence>(v) || py::isinstance<py::str>(v))
           throw py::type_error("pins must be a sequence of vertex tuples, one vertex per polygon");
         for (py::handle pin : v.cast<py::sequence>()) {
           if (!py::isinstance<py::sequence>(pin) || py::isinstance<py::str>(pin))
             throw py::type_error("pins: each pin is a tuple of vertex numbers, one per polygon");
           std::vector<long> vertices;
           for (py::handle x : pin.cast<py::sequence>()) {
             long vertex = number_from<long>(x, "pins");
             if (vertex < 0) throw py::value_error("pins: vertex numbers must not be negative, got " + std::to_string(vertex));
             vertices.push_back(vertex);
           }
           c.pins.push_back(std::move(vertices));
         }
       }},
      CM_NUMBER_OPTION(pin_corners_deg),
      CM_NUMBER_OPTION(max_edge),
      CM_NUMBER_OPTION(time_limit),
  };
  return setters;
}

// --- the call --------------------------------------------------------------

// The Python progress callable (None: none) as the relay's function; the
// core calls it without the GIL, so it takes the GIL first.
// Ctrl-C is checked here too (the main thread's pending signals): a long
// call stops, and KeyboardInterrupt comes out of it.
compatmesh::ProgressFn python_progress(const py::object &progress)
{
  return [&progress](double fraction, const char *stage) {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    return progress && !progress.is_none() && bool(py::bool_(progress(fraction, stage)));
  };
}

// Exception types made at import; kept for the process's life (a handle,
// so nothing is released after the interpreter is gone).
py::handle input_error_type;  // compatmesh.InputError
py::handle cancelled_type;    // compatmesh.Cancelled
struct InputErrorTag {};
struct CancelledTag {};

[[noreturn]] void raise_failure(const cm_result *result, cm_status status)
{
  std::string message = result ? cm_result_message(result) : "out of memory";
  if (status == CM_ERR_NO_MEMORY) throw std::bad_alloc();
  if (status == CM_ERR_CANCELLED) {
    PyErr_SetString(cancelled_type.ptr(), message.c_str());
    throw py::error_already_set();
  }
  if (status == CM_ERR_INTERNAL || status == CM_ERR_PRECISION) throw std::runtime_error(message);
  long polygon = -1, vertex = -1, other = -1;
  cm_result_error_location(result, &polygon, &vertex, &other);
  raise_input_error(message, status, polygon, vertex, other);
}

[[noreturn]] void raise_input_error(const std::string &message, cm_status status, long polygon,
                                   long vertex, long other)
{
  py::object error = input_error_type(message);
  error.attr("status") = cm_status_string(status);
  error.attr("polygon") = polygon;
  error.attr("vertex") = vertex;
  error.attr("other_vertex") = other;
  PyErr_SetObject(input_error_type.ptr(), error.ptr());
  throw py::error_already_set();
}

template <class T>
py::array_t<T> copy_array(const T *data, std::size_t rows, std::size_t columns)
{
  py::array_t<T> a(columns == 1 ? std::vector<py::ssize_t>{py::ssize_t(rows)}
                                : std::vector<py::ssize_t>{py::ssize_t(rows), py::ssize_t(columns)});
  if (rows > 0 && columns > 0) std::memcpy(a.mutable_data(), data, rows * columns * sizeof(T));
  return a;
}

// The vertices of geometry g in the input's dimension: input vertices
// as given, Steiner vertices mapped from the plane.
// Geometry g; for n x 3 input the boundary vertices come from the input's
// points (its own vertices bit-identical, points added on its edges
// interpolated along the 3D edge) and the rest are lifted into its plane.
py::array_t<double> vertices_of(const cm_result *result, std::size_t g, const Polygon &polygon)
{
  std::size_t nv = cm_result_num_vertices(result), n = cm_result_stats(result)->n, size = polygon.size();
  const double *xy = cm_result_vertices(result, g);
  if (!polygon.spatial) return copy_array(xy, nv, 2);
  py::array_t<double> a({py::ssize_t(nv), py::ssize_t(3)});
  double *out = a.mutable_data();
  for (std::size_t v = 0; v < n; v++) {
    double t = 0;
    std::size_t e = std::size_t(cm_result_boundary_source(result, g, v, &t));
    const double *p = polygon.xyz.data() + 3 * e, *q = polygon.xyz.data() + 3 * ((e + 1) % size);
    for (int c = 0; c < 3; c++) out[3 * v + c] = t == 0 ? p[c] : p[c] + t * (q[c] - p[c]);
  }
  for (std::size_t v = n; v < nv; v++) {
    std::array<double, 3> p = polygon.frame.to_space(xy[2 * v], xy[2 * v + 1]);
    std::memcpy(out + 3 * v, p.data(), sizeof p);
  }
  return a;
}

py::dict quality_dict(const cm_quality &q)
{
  py::dict d;
  d["min_angle_deg"] = q.min_angle_deg;
  d["max_angle_deg"] = q.max_angle_deg;
  d["pct_below_10deg"] = q.pct_below_10deg;
  d["pct_below_15deg"] = q.pct_below_15deg;
  d["pct_below_20deg"] = q.pct_below_20deg;
  return d;
}

py::dict stats_of(const cm_result *result)
{
  const cm_stats *s = cm_result_stats(result);
  py::dict stats;
  stats["n"] = s->n;
  stats["k"] = s->k;
  stats["vertices"] = s->vertices;
  stats["steiner"] = s->steiner;
  stats["holes"] = s->holes;
  stats["bridges"] = s->bridges;
  stats["holes_moved"] = s->holes_moved;
  stats["pairings_built"] = s->pairings_built;
  stats["pairings_remeshed"] = s->pairings_remeshed;
  stats["time_limit_reached"] = bool(s->time_limit_reached);
  stats["triangles"] = s->triangles;
  stats["reversed_input"] = bool(s->reversed_input);
  stats["fallback_count"] = s->fallback_count;
  stats["steiner_before_remesh"] = s->steiner_before_remesh;
  stats["remesh_iterations"] = s->remesh_iterations;
  stats["remesh_aim_deg"] = s->remesh_aim_deg;
  stats["seconds_validate"] = s->seconds_validate;
  stats["seconds_build"] = s->seconds_build;
  stats["seconds_remesh"] = s->seconds_remesh;
  stats["seconds_check"] = s->seconds_check;
  stats["seconds_ceiling"] = s->seconds_ceiling;
  stats["ceiling_deg"] = s->ceiling_deg;
  stats["corner_fan_cap_deg"] = s->corner_fan_cap_deg;
  stats["correspondence_bound_deg"] = s->correspondence_bound_deg;
  stats["modulus_distortion"] = s->modulus_distortion;
  stats["distortion_quad"] = py::make_tuple(s->distortion_quad[0], s->distortion_quad[1], s->distortion_quad[2],
                                            s->distortion_quad[3]);
  // 0 in the core when not computed (no auto choice): None here
  stats["correspondence_bound_before_deg"] =
      s->correspondence_bound_before_deg > 0 ? py::object(py::float_(s->correspondence_bound_before_deg)) : py::none();
  stats["correspondence_choice"] = cm_correspondence_choice_name(s->correspondence_choice);
  py::list quality, quality_before;
  for (std::size_t g = 0; g < s->k; g++) {
    cm_quality q;
    cm_result_quality(result, g, &q);
    quality.append(quality_dict(q));
    cm_result_quality_before(result, g, &q);
    quality_before.append(quality_dict(q));
  }
  stats["quality"] = quality;
  stats["quality_before_remesh"] = quality_before;
  return stats;
}

// What triangulate, morph and sweep have in common: the points, the cells
// by meshio's cell type names, the statistics and the quality; each kind
// adds its own fields and to_meshio().
struct Output {
  py::object points;
  py::dict cells;
  py::dict stats;
  py::object quality;
};

struct Result : Output {
  py::array_t<int32_t> faces;
  py::list vertices;
  py::list boundary_source;
  py::dict halfedges;
};

// Morph and sweep keep the fields they returned as a dict, readable as
// attributes and by key.
struct Morph : Output {
  py::dict fields;
};

struct Sweep : Output {
  py::dict fields;
  // The boundary's faces (cm_sweep_boundary_faces: 4 node indices each,
  // the 4th -1 for a triangle), sorted by group, over the prisms [0] and
  // the tetrahedra [1], with each group's run of faces
  // (cm_sweep_boundary_group_offsets; empty where there are no faces).
  std::vector<int32_t> faces[2];
  std::vector<std::size_t> group_offsets[2];
  std::vector<int64_t> face_cells[2];  // cm_sweep_boundary_cells
  std::vector<std::string> group_names;  // cm_sweep_boundary_group_name
};

Result make_result(const cm_result *r, const std::vector<Polygon> &polygons)
{
  Result result;
  std::size_t nv = cm_result_num_vertices(r), nh = cm_result_num_halfedges(r),
              nt = cm_result_num_triangles(r);
  result.faces = copy_array(cm_result_triangles(r), nt, 3);
  for (std::size_t g = 0; g < polygons.size(); g++) result.vertices.append(vertices_of(r, g, polygons[g]));
  result.halfedges["next"] = copy_array(cm_result_halfedge_next(r), nh, 1);
  result.halfedges["to_vertex"] = copy_array(cm_result_halfedge_to_vertex(r), nh, 1);
  result.halfedges["face"] = copy_array(cm_result_halfedge_face(r), nh, 1);
  result.halfedges["vertex_halfedge"] = copy_array(cm_result_vertex_halfedge(r), nv, 1);
  result.halfedges["face_halfedge"] = copy_array(cm_result_face_halfedge(r), nt, 1);
  result.stats = stats_of(r);
  result.points = result.vertices;
  result.cells["triangle"] = result.faces;
  result.quality = result.stats["quality"];
  std::size_t n = cm_result_stats(r)->n;
  for (std::size_t g = 0; g < polygons.size(); g++) {
    py::array_t<std::int64_t> edge{py::ssize_t(n)};
    py::array_t<double> t{py::ssize_t(n)};
    for (std::size_t i = 0; i < n; i++) edge.mutable_at(i) = cm_result_boundary_source(r, g, i, t.mutable_data() + i);
    py::dict source;
    source["edge"] = edge;
    source["t"] = t;
    result.boundary_source.append(source);
  }
  return result;
}

// Reads the polygons and runs the core with the keyword options of
// triangulate(); `function` names the caller in messages. On success the
// result is returned and the polygons are left in *polygons.
ResultPtr run_triangulation(py::handle polygons_in, const py::dict &kwargs, const char *function,
                            std::vector<Polygon> *polygons, Callbacks *callbacks, bool loft = false)
{
  double tolerance = compatmesh::kDefaultPlanarityTolerance;
  cm_options options;
  cm_options_init(&options);
  for (auto item : kwargs) {
    std::string name = item.first.cast<std::string>();
    if (name == "planarity_tolerance") {
      tolerance = number_from<double>(item.second, "planarity_tolerance");
      if (tolerance < 0) throw py::value_error("planarity_tolerance must not be negative, got " + std::to_string(tolerance));
      continue;
    }
    const OptionSetter *setter = nullptr;
    for (const OptionSetter &s : option_setters())
      if (name == s.name) setter = &s;
    if (!setter)
      throw py::type_error(std::string(function) + "() got an unexpected keyword argument '" + name + "'");
    setter->set(options, item.second, *callbacks);
  }

  // Polygons in space have their frames aligned, each plane's axes carried
  // from the one before: fitted axes follow each polygon's own spread (two
  // sections of a pipe may get axes a quarter turn apart), and a
  // correspondence chosen in the plane would twist them. A loft's (morph(),
  // sweep()) are fitted following their winding, then their normals turned
  // along the loft (align_frames).
  const compatmesh::NormalSign sign = loft ? compatmesh::NormalSign::FollowWinding : compatmesh::NormalSign::Canonical;
  for (py::handle item : polygons_in) polygons->push_back(read_polygon(item, polygons->size(), tolerance, sign));
  std::vector<Polygon *> spatial;
  for (Polygon &p : *polygons)
    if (p.spatial) spatial.push_back(&p);
  compatmesh::align_sections(spatial, loft);
  std::vector<const double *> data;
  std::vector<std::size_t> counts;
  std::vector<cm_loops> loops;
  bool holes = false;
  for (const Polygon &p : *polygons) {
    data.push_back(p.xy.data());
    counts.push_back(p.size());
    holes |= p.loop_sizes.size() > 1;
  }
  for (const Polygon &p : *polygons)
    loops.push_back(cm_loops{p.xy.data(), p.loop_sizes.empty() ? &counts[loops.size()] : p.loop_sizes.data(),
                             p.loop_sizes.empty() ? 1 : p.loop_sizes.size()});
  // Without a word from the caller, pins or different counts (of any loop)
  // decide, as on the command line.
  if (!callbacks->correspondence_given)
    options.correspondence = cm_correspondence_by_counts(loops.data(), loops.size(),
                                                         !callbacks->pins.empty() || options.pin_corners_deg > 0);
  for (std::size_t j = 0; j < callbacks->pins.size(); j++) {
    if (callbacks->pins[j].size() != polygons->size())
      throw py::value_error("pins: pin " + std::to_string(j) + " has " + std::to_string(callbacks->pins[j].size()) +
                            " vertices for " + std::to_string(polygons->size()) + " polygons");
    for (long v : callbacks->pins[j]) callbacks->pin_data.push_back(std::size_t(v));
  }
  options.pins = callbacks->pin_data.data();
  options.num_pins = callbacks->pins.size();

  ProgressRelay relay(python_progress(callbacks->progress));
  relay.attach(options);
  cm_result *raw = nullptr;
  cm_status status;
  {
    py::gil_scoped_release no_gil;
    status = holes ? cm_triangulate_loops(loops.data(), polygons->size(), &options, &raw)
                   : cm_triangulate_polygons(data.data(), counts.data(), polygons->size(), &options, &raw);
  }
  ResultPtr result(raw);
  relay.rethrow();
  if (status != CM_OK) raise_failure(raw, status);
  return result;
}

Result triangulate(py::object polygons_in, py::kwargs kwargs)
{
  std::vector<Polygon> polygons;
  Callbacks callbacks;
  ResultPtr result = run_triangulation(polygons_in, kwargs, "triangulate", &polygons, &callbacks);
  return make_result(result.get(), polygons);
}

// --- morph and sweep ---------------------------------------------------------

// A failed morph or sweep call: the core's message as a ValueError when the
// arguments were at fault, RuntimeError when its own check failed.
[[noreturn]] void raise_step_failure(cm_status status, const char *message)
{
  std::string text = message && message[0] ? message : cm_status_string(status);
  if (status == CM_ERR_NO_MEMORY) throw std::bad_alloc();
  if (status == CM_ERR_CANCELLED) {
    PyErr_SetString(cancelled_type.ptr(), text.c_str());
    throw py::error_already_set();
  }
  if (status == CM_ERR_INTERNAL || status == CM_ERR_PRECISION) throw std::runtime_error(text);
  throw py::value_error(text);
}

// Morph and sweep work in the plane: their sections are n x 2, or n x 3
// for every polygon (in planes z = constant, or a loft's).
void require_planar(const std::vector<Polygon> &polygons, const char *function)
{
  for (std::size_t g = 0; g < polygons.size(); g++)
    if (polygons[g].spatial)
      throw py::value_error(std::string(function) + ": polygon " + std::to_string(g) +
                            ": expected an n x 2 array, or n x 3 arrays for every polygon (in planes z = constant, "
                            "or in any planes for a loft)");
}

// The morph of the triangulated polygons, progress reported like the
// triangulation's.
MorphPtr make_morph(const cm_result *result, cm_morph_method method, ProgressRelay &relay)
{
  cm_morph_options options;
  cm_morph_options_init(&options);
  options.method = method;
  relay.attach(options);
  cm_morph *raw = nullptr;
  cm_status status;
  {
    py::gil_scoped_release no_gil;
    status = cm_morph_create(result, &options, &raw);
  }
  MorphPtr morph(raw);
  relay.rethrow();
  if (status != CM_OK) raise_step_failure(status, raw ? cm_morph_message(raw) : nullptr);
  return morph;
}

const std::vector<std::pair<const char *, cm_morph_method>> morph_method_names = {
    {"convex", CM_MORPH_CONVEX}, {"linear", CM_MORPH_LINEAR}};

// The times asked for: t (a number or a sequence) or frames (evenly spaced,
// both ends included), exactly one of them.
std::vector<double> morph_times(py::object t, py::object frames)
{
  if (t.is_none() == frames.is_none()) throw py::type_error("morph() takes exactly one of t and frames");
  std::vector<double> times;
  if (!frames.is_none()) {
    long count = number_from<long>(frames, "frames");
    if (count < 2 || count > kMaxFrames)
      throw py::value_error("morph: frames must be 2 to " + std::to_string(kMaxFrames) + ", got " +
                            std::to_string(count));
    for (long f = 0; f < count; f++) times.push_back(f + 1 == count ? 1.0 : double(f) / double(count - 1));
    return times;
  }
  if (py::isinstance<py::float_>(t) || py::isinstance<py::int_>(t)) return {t.cast<double>()};
  FloatArray a = real_array(t, "morph: t");
  if (a.ndim() != 1) throw py::type_error("morph: t must be a number or a 1-D sequence of numbers");
  if (a.shape(0) > kMaxFrames)
    throw py::value_error("morph: at most " + std::to_string(kMaxFrames) + " times, got " + std::to_string(a.shape(0)));
  times.assign(a.data(), a.data() + a.shape(0));
  return times;
}

// A section given in space in a plane z = constant (n x 3 arrays, every
// loop's z one value up to the rounding of single precision, as the
// command line's readers allow: 16 float epsilons of the coordinates'
// size): its loops' x and y, and *z; else the object as it is and no z.
py::object section_in_plane_z(py::handle polygon, std::size_t index, double *z, bool *has_z)
{
  *has_z = false;
  py::object geometry = geo_geometry(polygon);
  py::object object = geometry.is_none() ? py::reinterpret_borrow<py::object>(polygon) : geo_loops(geometry, index);
  bool several = is_loop_list(object);
  py::list flat;
  double z0 = 0;
  std::size_t l = 0;
  for (py::handle loop : several ? py::iter(object) : py::iter(py::make_tuple(object))) {
    py::array any = py::array::ensure(loop);
    if (!any) {
      PyErr_Clear();
      return object;
    }
    FloatArray a = real_array(loop, "polygon " + std::to_string(index));
    if (a.ndim() != 2 || a.shape(1) != 3 || a.shape(0) == 0) return object;
    if (l++ == 0) z0 = *a.data(0, 2);
    for (py::ssize_t i = 0; i < a.shape(0); i++) {
      double x = *a.data(i, 0), y = *a.data(i, 1), zi = *a.data(i, 2);
      double size = std::max(std::max(std::fabs(x), std::fabs(y)), std::max(std::fabs(zi), std::fabs(z0)));
      if (!(std::fabs(zi - z0) <= 16 * FLT_EPSILON * size)) return object;
    }
    flat.append(a[py::make_tuple(py::slice(0, a.shape(0), 1), py::slice(0, 2, 1))]);
  }
  *z = z0, *has_z = true;
  return several ? py::object(flat) : py::object(flat[0]);
}

// The polygons as the triangulation takes them (`function` names the call
// in errors). Sections for a loft (every polygon an n x 3 array and not
// all of them in planes z = constant): *loft, the polygons as given. Else
// the polygons passed on in the plane (x, y), and *z each one's z where
// every polygon is n x 3 in a plane z = constant (else *z empty); only
// some of them so is an error.
py::object placed_sections(py::object polygons_in, const std::string &function, bool *loft, std::vector<double> *z)
{
  py::list flat;
  std::vector<double> own;
  std::size_t with_z = 0;
  bool arrays = true;  // every polygon so far an n x 3 array
  for (py::handle polygon : polygons_in) {
    const std::size_t index = flat.size();
    if (arrays && (!geo_geometry(polygon).is_none() || is_loop_list(polygon))) arrays = false;
    if (arrays) {
      FloatArray a = real_array(polygon, "polygon " + std::to_string(index));
      arrays = a.ndim() == 2 && a.shape(1) == 3;
    }
    double zg = 0;
    bool has_z = false;
    flat.append(section_in_plane_z(polygon, index, &zg, &has_z));
    own.push_back(zg), with_z += has_z;
  }
  *loft = arrays && with_z < own.size();
  if (*loft) return polygons_in;
  if (with_z > 0 && with_z < own.size())
    throw py::value_error(function + ": some polygons lie in a plane z = constant and some do not; give all of them z" +
                          (function == "sweep" ? " or pass height / heights" : ""));
  if (with_z > 0) *z = own;
  return flat;
}

// The sections' own z (placed_sections) as the sweep's heights, as the
// command line takes its inputs' z: none where they are all equal (a
// drawing), else they must increase.
void sweep_heights(std::vector<double> *z)
{
  const std::vector<double> &own = *z;
  if (std::all_of(own.begin(), own.end(), [&](double v) { return v == own[0]; })) {
    z->clear();
    return;
  }
  for (std::size_t g = 1; g < own.size(); g++)
    if (!(own[g] > own[g - 1]))
      throw py::value_error("sweep: polygon " + std::to_string(g) + " lies at z = " + py::str(py::float_(own[g])).cast<std::string>() +
                            ", not above polygon " + std::to_string(g - 1) + " at z = " +
                            py::str(py::float_(own[g - 1])).cast<std::string>() +
                            "; the polygons' z must increase (or pass height / heights)");
}

// The loft's frames (cm_sweep_options.frames): each polygon's plane.
std::vector<double> loft_frames(const std::vector<Polygon> &polygons)
{
  std::vector<double> frames;
  for (const Polygon &p : polygons) compatmesh::append_loft_frame(p.frame, frames);
  return frames;
}

// The sections in space, F x nv x 3, between the polygons' planes (frames
// as cm_sweep_options.frames takes them): at a polygon's own time
// (cm_morph_section gives its geometry bit for bit) its vertices as
// vertices_of gives them; in between cm_loft_section, as the sweep's loft
// places its nodes. Between planes z = constant (polygons not spatial),
// x and y are the section's own and z the planes' blend (a polygon's own
// z at its time).
py::array sections_in_space(const cm_result *result, const std::vector<Polygon> &polygons,
                            const std::vector<double> &frames, const std::vector<double> &times,
                            const py::array_t<double> &plane)
{
  const std::size_t nv = cm_result_num_vertices(result), k = polygons.size();
  const bool flat = k > 0 && !polygons[0].spatial;
  py::array_t<double> out({py::ssize_t(times.size()), py::ssize_t(nv), py::ssize_t(3)});
  for (std::size_t f = 0; f < times.size(); f++) {
    const double *xy = plane.data() + 2 * nv * f;
    double *p = out.mutable_data() + 3 * nv * f;
    std::size_t own = k;
    for (std::size_t g = 0; g < k && own == k; g++)
      if (std::memcmp(xy, cm_result_vertices(result, g), 2 * nv * sizeof *xy) == 0) own = g;
    if (own < k && !flat) {
      py::array_t<double> v = vertices_of(result, own, polygons[own]);
      std::memcpy(p, v.data(), 3 * nv * sizeof *p);
      continue;
    }
    cm_loft_section(frames.data(), k, times[f], xy, nv, p);
    if (flat)
      for (std::size_t i = 0; i < nv; i++)
        p[3 * i] = xy[2 * i], p[3 * i + 1] = xy[2 * i + 1], p[3 * i + 2] = own < k ? frames[9 * own + 2] : p[3 * i + 2];
  }
  return out;
}

// The planes z = z[g] as cm_sweep_options.frames takes them.
std::vector<double> plane_z_frames(const std::vector<double> &z)
{
  std::vector<double> frames;
  for (double zg : z) frames.insert(frames.end(), {0, 0, zg, 1, 0, 0, 0, 1, 0});
  return frames;
}

Morph morph(py::object polygons_in, py::object t, py::object frames, py::object morph_method,
               py::kwargs kwargs)
{
  std::vector<double> times = morph_times(t, frames);
  cm_morph_method method = enum_from(morph_method, "morph_method", morph_method_names);
  std::vector<Polygon> polygons;
  Callbacks callbacks;
  // Sections in space, or n x 3 in planes z = constant: frames between their planes.
  bool loft;
  std::vector<double> own_z;
  py::object planar = placed_sections(polygons_in, "morph", &loft, &own_z);
  ResultPtr result = run_triangulation(planar, kwargs, "morph", &polygons, &callbacks, loft);
  if (!loft) require_planar(polygons, "morph");
  ProgressRelay relay(python_progress(callbacks.progress));
  MorphPtr m = make_morph(result.get(), method, relay);

  std::size_t nv = cm_result_num_vertices(result.get()), frame_count = times.size();
  py::array_t<double> sections({py::ssize_t(frame_count), py::ssize_t(nv), py::ssize_t(2)});
  py::array_t<std::int64_t> inverted{py::ssize_t(frame_count)};
  py::array_t<double> min_angle{py::ssize_t(frame_count)};
  for (std::size_t f = 0; f < frame_count; f++) {
    std::size_t bad = 0;
    double angle = 0;
    cm_status status;
    {
      py::gil_scoped_release no_gil;
      status = cm_morph_section(m.get(), times[f], sections.mutable_data() + 2 * nv * f, &bad, &angle);
    }
    if (status != CM_OK) raise_step_failure(status, cm_morph_message(m.get()));
    inverted.mutable_at(f) = std::int64_t(bad);
    min_angle.mutable_at(f) = angle;
  }
  Morph out;
  py::dict &fields = out.fields;
  fields["faces"] = copy_array(cm_result_triangles(result.get()), cm_result_num_triangles(result.get()), 3);
  fields["t"] = copy_array(times.data(), frame_count, 1);
  if (loft || !own_z.empty())
    fields["sections"] = sections_in_space(result.get(), polygons, loft ? loft_frames(polygons) : plane_z_frames(own_z),
                                           times, sections);
  else
    fields["sections"] = py::array(sections);
  fields["inverted"] = inverted;
  fields["min_angle_deg"] = min_angle;
  fields["n"] = polygons.empty() ? 0 : polygons[0].size();
  out.points = fields["sections"];
  out.cells["triangle"] = fields["faces"];
  out.stats = stats_of(result.get());
  py::list quality;
  for (std::size_t f = 0; f < frame_count; f++) {
    py::dict q;
    q["min_angle_deg"] = min_angle.at(f);
    q["inverted"] = inverted.at(f);
    quality.append(q);
  }
  out.quality = quality;
  return out;
}


Sweep sweep(py::object polygons_in, py::object sections, py::object height, py::object heights,
               bool tets, py::object wall_corner_deg, bool ruled, py::kwargs kwargs)
{
  cm_sweep_options options;
  cm_sweep_options_init(&options);
  bool automatic = py::isinstance<py::str>(sections) && sections.cast<std::string>() == "auto";
  options.sections = automatic ? 0 : number_from<std::size_t>(sections, "sections");
  if (!automatic && (options.sections < 2 || options.sections > CM_SWEEP_MAX_SECTIONS))
    throw py::value_error("sweep: sections must be 'auto' or 2 to " + std::to_string(CM_SWEEP_MAX_SECTIONS) +
                          ", got " + std::to_string(options.sections));
  options.tets = tets ? 1 : 0;
  options.wall_corner_deg = number_from<double>(wall_corner_deg, "wall_corner_deg");
  options.ruled = ruled ? 1 : 0;
  if (!height.is_none()) {
    options.height = number_from<double>(height, "height");
    // 0 would ask the core for its default height: a given height must be positive.
    if (!(options.height > 0)) throw py::value_error("sweep: height must be positive, got " + py::str(height).cast<std::string>());
  }
  std::vector<double> z;
  if (!heights.is_none()) {
    if (!height.is_none()) throw py::type_error("sweep() takes height or heights, not both");
    FloatArray a = real_array(heights, "sweep: heights");
    if (a.ndim() != 1) throw py::type_error("sweep: heights must be a 1-D sequence of numbers");
    z.assign(a.data(), a.data() + a.shape(0));
  }
  // Sections in planes that are not all z = constant: a loft between their
  // planes, each section read in its own plane, the first normal towards
  // the second section, each next on the side of the one before and each
  // plane's axes carried from the one before (compatmesh::align_frames: a
  // section listed the other way round then runs clockwise in its plane).
  bool loft;
  std::vector<double> own;  // the sections' own z, when they give them
  py::object planar = placed_sections(polygons_in, "sweep", &loft, &own);
  if (loft && !(height.is_none() && heights.is_none()))
    throw py::value_error("sweep: the polygons lie in planes of space, which place them: give no height or heights");
  sweep_heights(&own);
  if (heights.is_none() && height.is_none() && !own.empty()) z = own;
  std::vector<Polygon> polygons;
  Callbacks callbacks;
  ResultPtr result = run_triangulation(planar, kwargs, "sweep", &polygons, &callbacks, loft);
  std::vector<double> frames;
  if (loft) frames = loft_frames(polygons), options.frames = frames.data();
  else require_planar(polygons, "sweep");
  if (!z.empty() || !heights.is_none()) {
    if (z.size() != polygons.size())
      throw py::value_error("sweep: heights has " + std::to_string(z.size()) + " values for " +
                            std::to_string(polygons.size()) + " polygons");
    options.heights = z.data();
  }  // else the core's default height: the largest bounding-box diagonal
  ProgressRelay relay(python_progress(callbacks.progress));
  MorphPtr m = make_morph(result.get(), CM_MORPH_CONVEX, relay);
  relay.attach(options);
  cm_sweep *raw = nullptr;
  cm_status status;
  {
    py::gil_scoped_release no_gil;
    status = cm_sweep_create(m.get(), &options, &raw);
  }
  SweepPtr w(raw);
  relay.rethrow();
  if (status != CM_OK) raise_step_failure(status, raw ? cm_sweep_message(raw) : nullptr);

  Sweep swept;
  for (int t = 0; t < 2; t++) {
    const std::size_t nf = cm_sweep_num_boundary_faces(w.get(), t);
    const int32_t *f = cm_sweep_boundary_faces(w.get(), t);
    const std::size_t *offsets = cm_sweep_boundary_group_offsets(w.get(), t);
    if (nf) {
      swept.faces[t].assign(f, f + 4 * nf);
      swept.group_offsets[t].assign(offsets, offsets + cm_sweep_num_boundary_groups(w.get()) + 1);
      const int64_t *cells = cm_sweep_boundary_cells(w.get(), t);
      swept.face_cells[t].assign(cells, cells + 2 * nf);
    }
  }
  for (std::size_t g = 0; g < cm_sweep_num_boundary_groups(w.get()); g++)
    swept.group_names.push_back(cm_sweep_boundary_group_name(w.get(), g));
  py::dict &out = swept.fields;
  out["nodes"] = copy_array(cm_sweep_nodes(w.get()), cm_sweep_num_nodes(w.get()), 3);
  out["prisms"] = copy_array(cm_sweep_prisms(w.get()), cm_sweep_num_prisms(w.get()), 6);
  out["tets"] = copy_array(cm_sweep_tets(w.get()), cm_sweep_num_tets(w.get()), 4);
  out["section_z"] = copy_array(cm_sweep_section_z(w.get()), cm_sweep_num_sections(w.get()), 1);
  out["volume"] = cm_sweep_volume(w.get());
  out["height"] = cm_sweep_height(w.get());
  out["height_is_default"] = cm_sweep_height_is_default(w.get()) != 0;
  out["morph"] = cm_morph_method_name(cm_sweep_morph_method(w.get()));
  cm_sweep_quality q;
  cm_sweep_get_quality(w.get(), &q);
  py::dict quality;
  quality["min_dihedral_deg"] = q.min_dihedral_deg;
  quality["max_dihedral_deg"] = q.max_dihedral_deg;
  quality["min_scaled_jacobian"] = q.min_scaled_jacobian;
  quality["max_aspect_ratio"] = q.max_aspect_ratio;
  quality["max_prism_flatness"] = q.max_flatness;
  quality["flat_prisms"] = q.flat_prisms;
  out["quality"] = quality;
  swept.points = out["nodes"];
  swept.cells["wedge"] = out["prisms"];
  if (tets) swept.cells["tetra"] = out["tets"];
  swept.stats = stats_of(result.get());
  swept.quality = quality;
  return swept;
}


// --- meshio ------------------------------------------------------------------
// to_meshio() and write() hand the arrays to meshio, imported when first
// used so that the module works without it.

py::module_ import_meshio(const char *function)
{
  try {
    return py::module_::import("meshio");
  } catch (py::error_already_set &e) {
    if (!e.matches(PyExc_ImportError)) throw;
    PyErr_SetString(PyExc_ImportError, (std::string(function) +
                                        " needs meshio (the Debian package python3-meshio)").c_str());
    throw py::error_already_set();
  }
}

// n x 2 or n x 3 points as a new n x 3 float64 array, z = 0 for planar
// points: the formats meshio writes hold 3D points, so a written file reads
// back as it was given.
py::array_t<double> points_3d(py::handle points)
{
  FloatArray a = FloatArray::ensure(points);
  std::size_t n = std::size_t(a.shape(0)), d = std::size_t(a.shape(1));
  py::array_t<double> out({py::ssize_t(n), py::ssize_t(3)});
  double *o = out.mutable_data();
  const double *in = a.data();
  for (std::size_t i = 0; i < n; i++)
    for (std::size_t c = 0; c < 3; c++) o[3 * i + c] = c < d ? in[d * i + c] : 0.0;
  return out;
}

py::object meshio_mesh(py::handle points, const char *cell_type, py::handle cells, const char *function)
{
  py::list blocks;
  blocks.append(py::make_tuple(cell_type, cells));
  return import_meshio(function).attr("Mesh")(points_3d(points), blocks);
}

// which (a geometry or frame number; negative counts from the end) checked
// against count.
std::size_t index_in(py::handle which, std::size_t count, const char *what, const char *function)
{
  long i = number_from<long>(which, what);
  if (i < -long(count) || i >= long(count))
    throw py::index_error(std::string(function) + ": " + what + " " + std::to_string(i) + " is out of range (0 to " +
                          std::to_string(long(count) - 1) + ")");
  return std::size_t(i < 0 ? i + long(count) : i);
}

py::object result_to_meshio(const Result &r, py::object geometry)
{
  std::size_t k = py::len(r.vertices);
  auto one = [&](std::size_t g) { return meshio_mesh(r.vertices[g], "triangle", r.faces, "to_meshio"); };
  if (!geometry.is_none()) return one(index_in(geometry, k, "geometry", "to_meshio"));
  py::list meshes;
  for (std::size_t g = 0; g < k; g++) meshes.append(one(g));
  return meshes;
}

py::object morph_to_meshio(const Morph &m, py::object frame)
{
  py::array sections = py::array::ensure(m.fields["sections"]);
  std::size_t count = std::size_t(sections.shape(0));
  auto one = [&](std::size_t f) {
    return meshio_mesh(sections[py::int_(f)], "triangle", m.fields["faces"], "to_meshio");
  };
  if (!frame.is_none()) return one(index_in(frame, count, "frame", "to_meshio"));
  py::list meshes;
  for (std::size_t f = 0; f < count; f++) meshes.append(one(f));
  return meshes;
}

// Which cells a call on the sweep means (cells: 'wedge', 'tetra', or None
// for the tetrahedra where the sweep has them): true for the tetrahedra.
bool sweep_tets(const Sweep &s, py::object cells, const char *function)
{
  bool has_tets = s.cells.contains("tetra");
  if (!cells.is_none() && !py::isinstance<py::str>(cells))
    throw py::type_error(std::string(function) + ": cells must be 'wedge', 'tetra' or None");
  std::string kind = cells.is_none() ? (has_tets ? "tetra" : "wedge") : py::str(cells).cast<std::string>();
  if (kind == "tetra" && !has_tets)
    throw py::value_error(std::string(function) + ": this sweep has no tetrahedra (sweep(..., tets=True) makes them)");
  if (kind != "tetra" && kind != "wedge")
    throw py::value_error(std::string(function) + ": unknown cells '" + kind + "' (known: 'wedge', 'tetra')");
  return kind == "tetra";
}

// The sweep as a meshio.Mesh: the prisms (meshio's wedge is VTK's: the
// bottom clockwise seen from the top, so a, c, b then d, f, e; with
// gmsh_order Gmsh's, the prisms as they are, for the writers that want it)
// or the tetrahedra.
py::object sweep_mesh(const Sweep &s, py::object cells, bool gmsh_order, const char *function)
{
  if (sweep_tets(s, cells, function)) return meshio_mesh(s.fields["nodes"], "tetra", s.fields["tets"], function);
  if (gmsh_order) return meshio_mesh(s.fields["nodes"], "wedge", s.fields["prisms"], function);
  auto gmsh = py::array_t<int32_t>::ensure(s.fields["prisms"]);
  py::ssize_t p = gmsh.shape(0);
  py::array_t<int32_t> vtk({p, py::ssize_t(6)});
  static const int order[6] = {0, 2, 1, 3, 5, 4};
  for (py::ssize_t i = 0; i < p; i++)
    for (int c = 0; c < 6; c++) vtk.mutable_at(i, c) = gmsh.at(i, order[c]);
  return meshio_mesh(s.fields["nodes"], "wedge", vtk, function);
}

// Group name -> make(first, end): each boundary group's run of faces
// over the prisms (t = 0) or the tetrahedra (t = 1), in the core's order.
template <typename Make>
py::dict per_group(const Sweep &s, int t, Make make)
{
  const std::vector<std::size_t> &offsets = s.group_offsets[t];
  py::dict out;
  for (std::size_t k = 0; k < s.group_names.size(); k++)
    out[py::str(s.group_names[k])] = offsets.empty() ? make(0, 0) : make(offsets[k], offsets[k + 1]);
  return out;
}

// boundary(cells): group name -> its faces, k x 3 (triangles) or k x 4
// (the prisms' side quads).
py::dict sweep_boundary(const Sweep &s, py::object cells)
{
  int t = sweep_tets(s, cells, "boundary");
  const std::vector<int32_t> &f = s.faces[t];
  return per_group(s, t, [&](std::size_t start, std::size_t end) {
    py::ssize_t width = end > start && f[4 * start + 3] >= 0 ? 4 : 3;
    py::array_t<int32_t> faces({py::ssize_t(end - start), width});
    for (std::size_t r = start; r < end; r++)
      for (py::ssize_t c = 0; c < width; c++) faces.mutable_at(py::ssize_t(r - start), c) = f[4 * r + std::size_t(c)];
    return faces;
  });
}

// boundary_cells(cells): group name -> k x 2 int64 (cell, face), the
// faces of boundary(cells) in the same order.
py::dict sweep_boundary_cells(const Sweep &s, py::object cells)
{
  int t = sweep_tets(s, cells, "boundary_cells");
  const std::vector<int64_t> &c = s.face_cells[t];
  return per_group(s, t, [&](std::size_t start, std::size_t end) {
    py::array_t<int64_t> pairs({py::ssize_t(end - start), py::ssize_t(2)});
    if (end > start) std::memcpy(pairs.mutable_data(), c.data() + 2 * start, 2 * (end - start) * sizeof(int64_t));
    return pairs;
  });
}

py::object sweep_to_meshio(const Sweep &s, py::object cells) { return sweep_mesh(s, cells, false, "to_meshio"); }

// The path's extension, lower case ("" without one).
std::string lower_suffix(py::object path)
{
  return py::str(py::module_::import("pathlib").attr("Path")(path).attr("suffix").attr("lower")());
}

// The meshio format read_polygon() and write() use: file_format, else the
// one the path's extension names (None where meshio is left to tell);
// ".msh" is Gmsh's (meshio's first guess for it is ANSYS Fluent's, which
// Gmsh and the solvers reading Gmsh's files do not read, and its reader
// prints a blank line where that guess fails).
py::object meshio_format(py::object path, py::object file_format)
{
  if (!file_format.is_none()) return file_format;
  std::string suffix = lower_suffix(path);
  if (suffix == ".msh") return py::str("gmsh");
  py::object types = import_meshio("write").attr("extension_to_filetypes").attr("get")(suffix);
  return !types.is_none() && py::len(types) == 1 ? py::object(types[py::int_(0)]) : file_format;
}

// Does the format's 6-node wedge have Gmsh's corner order (the first
// triangle counter-clockwise seen from the second)? Gmsh's, Abaqus's and
// Nastran's do, VTK's is the mirror image, and meshio 5's writers pass the
// corners through as given.
bool gmsh_wedge_order(py::object format)
{
  if (format.is_none()) return false;
  std::string f = py::str(format);
  return f == "gmsh" || f == "gmsh22" || f == "abaqus" || f == "nastran";
}

// Runs write(written) on a temporary name beside path (ending in suffix
// after the path's own name), then renames it onto path, so that a write
// that fails leaves no partial file and an existing one as it was (with
// in_place, written is path itself: XDMF's heavy data file is named after
// it). The file gets the mode a new file would get.
template <class Write>
void write_atomically(py::object path, bool in_place, const std::string &suffix, Write write)
{
  py::module_ os = py::module_::import("os");
  py::object target = py::module_::import("pathlib").attr("Path")(path);
  py::object written = target;
  if (!in_place) {
    py::tuple made = py::module_::import("tempfile")
                         .attr("mkstemp")(py::arg("dir") = target.attr("parent"), py::arg("prefix") = ".",
                                          py::arg("suffix") = ".compatmesh-" + std::string(py::str(target.attr("name"))) +
                                                              suffix);
    os.attr("close")(made[0]);
    written = made[1];
  }
  try {
    write(written);
    if (!in_place) {
      py::object mask = os.attr("umask")(0);  // read, then put back: the mode a new file would get
      os.attr("umask")(mask);
      os.attr("chmod")(written, 0666 & ~mask.cast<int>());
      os.attr("replace")(written, target);
    }
  } catch (...) {
    if (!in_place && py::bool_(os.attr("path").attr("exists")(written))) os.attr("remove")(written);
    throw;
  }
}

// The sweep as the shared writers take it (export/volume_mesh.h): the
// cells in Gmsh's corner order, the boundary's faces in groups.
struct SweepVolume {
  py::array_t<double, py::array::c_style | py::array::forcecast> nodes;
  py::array_t<int32_t, py::array::c_style | py::array::forcecast> cells;
  std::vector<const char *> names;
  volume_mesh mesh;
  SweepVolume(const Sweep &s, bool tets)
      : nodes(decltype(nodes)::ensure(s.fields["nodes"])), cells(decltype(cells)::ensure(s.fields[tets ? "tets" : "prisms"]))
  {
    for (const std::string &name : s.group_names) names.push_back(name.c_str());
    mesh = {nodes.data(), std::size_t(nodes.shape(0)), cells.data(), std::size_t(cells.shape(0)), tets ? 1 : 0,
            s.faces[tets].data(), s.faces[tets].size() / 4, names.size(), names.data(), s.group_offsets[tets].data(),
            s.face_cells[tets].data()};
  }
};

// The Abaqus deck's boundary sets (export/abaqus_sets.h, as the command
// line appends them) appended to the file meshio wrote.
void append_abaqus_sets(const Sweep &s, bool tets, const std::string &file)
{
  const SweepVolume volume(s, tets);
  FILE *out = std::fopen(file.c_str(), "ab");
  bool ok = out && abaqus_write_sets(out, &volume.mesh, nullptr, nullptr) == 0;
  int error = errno;
  if (out && std::fclose(out) != 0) ok = false, error = errno;
  if (!ok) throw std::runtime_error("write: " + file + ": " + std::strerror(error ? error : EIO));
}

// write(path, which, file_format): one mesh through meshio.write, in the
// format meshio_format chose; Gmsh's files as text, as Gmsh itself writes
// them; written by write_atomically.
void write_mesh(py::object mesh, py::object path, py::object format,
                const std::function<void(const std::string &)> &after = nullptr)
{
  py::object write = import_meshio("write").attr("write");
  std::string f = format.is_none() ? "" : std::string(py::str(format));
  std::string suffix = lower_suffix(path);
  bool in_place = f == "xdmf" || suffix == ".xdmf" || suffix == ".xmf";
  try {
    write_atomically(path, in_place, "", [&](py::object written) {
      if (f == "gmsh" || f == "gmsh22")
        write(written, mesh, py::arg("file_format") = format, py::arg("binary") = false);
      else if (f == "abaqus")  // CalculiX reads at most 21 characters a number: 14 digits, as Gmsh writes them
        write(written, mesh, py::arg("file_format") = format, py::arg("float_fmt") = ".14g");
      else
        write(written, mesh, py::arg("file_format") = format);
      if (after) after(py::str(written));
    });
  } catch (py::error_already_set &e) {
    // meshio 5.0's Nastran writer asserts where a double needs more than
    // its 16-character field
    if (f != "nastran" || !e.matches(PyExc_AssertionError)) throw;
    throw std::runtime_error("write: meshio's Nastran writer cannot fit these coordinates in its 16-character "
                             "fields; `compatmesh sweep ... --out FILE.bdf` writes Nastran through Gmsh");
  }
}

#ifdef CM_PYTHON_HAVE_GMSH
// The sweep written by Gmsh itself (export/gmsh_volume.h, as the command
// line writes it), the format by file's extension: the cells, of order 1
// or 2, and the boundary's groups (a .msh file's named surfaces in format
// version 4.1 or 2.2, an Abaqus deck's sets, its title `title`). Gmsh's state is global to the process, and a
// user may have a session of their own open (Gmsh 4.8 cannot say whether
// it is initialised), so the write runs in a child process that starts
// and ends its own; its output goes to /dev/null, its error comes back
// through a pipe.
void write_sweep_gmsh(const Sweep &s, bool tets, const std::string &file, double version, int order,
                      const std::string &title)
{
  const SweepVolume volume(s, tets);
  const volume_mesh &mesh = volume.mesh;
  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) throw std::runtime_error(std::string("write: ") + std::strerror(errno));
  pid_t child = fork();
  if (child < 0) {
    close(pipe_fds[0]), close(pipe_fds[1]);
    throw std::runtime_error(std::string("write: ") + std::strerror(errno));
  }
  if (child == 0) {
    close(pipe_fds[0]);
    int quiet = open("/dev/null", O_WRONLY);
    if (quiet >= 0) dup2(quiet, 1), dup2(quiet, 2);
    char message[512] = "";
    const gmsh_write_options options = {version, 0, nullptr, order, title.c_str()};
    int failed = gmsh_write_volume(file.c_str(), &mesh, &options, message, sizeof message);
    if (failed && write(pipe_fds[1], message, std::strlen(message)) < 0) failed = 2;
    _exit(failed ? 1 : 0);
  }
  close(pipe_fds[1]);
  // The child's reply, without the GIL; an interrupt (KeyboardInterrupt)
  // stops the child and is raised, and the caller removes the temporary.
  std::string message;
  bool interrupted = false;
  for (;;) {
    char buffer[256];
    ssize_t got;
    {
      py::gil_scoped_release no_gil;
      got = read(pipe_fds[0], buffer, sizeof buffer);
    }
    if (got > 0) {
      message.append(buffer, std::size_t(got));
      continue;
    }
    if (got < 0 && errno == EINTR && PyErr_CheckSignals() == 0) continue;
    interrupted = got < 0 && errno == EINTR;
    break;
  }
  close(pipe_fds[0]);
  if (interrupted) kill(child, SIGKILL);
  int status = 0;
  {
    py::gil_scoped_release no_gil;
    while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
  }
  if (interrupted) throw py::error_already_set();
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("write: cannot write " + file + ": " +
                             (message.empty() ? std::string("the Gmsh writer's process failed") : message));
}
#endif

// write()'s choice among `count` meshes: `which`, or the only one.
py::object the_one(py::object which, size_t count, const char *what)
{
  if (!which.is_none()) return which;
  if (count != 1)
    throw py::value_error(std::string("write: give the ") + what + " to write (0 to " + std::to_string(count - 1) +
                          ")");
  return py::int_(0);
}

// A polygon from a file meshio reads: its "line" cells are the boundary
// edges, chained into closed loops, each loop in the order of its edges from
// the first edge of the file on it. More than one loop: the one of largest
// area is the outer loop, the others holes in file order.
py::object read_polygon_file(py::object path, py::object file_format)
{
  // GeoJSON (.geojson, .json): a Polygon, a Feature or a FeatureCollection
  // of one Feature, read by the json module, its rings as triangulate()
  // takes GeoJSON polygons
  std::string suffix = lower_suffix(path);
  if (file_format.is_none() && (suffix == ".geojson" || suffix == ".json")) {
    std::string where = "read_polygon: " + py::str(path).cast<std::string>();
    py::object text = py::module_::import("pathlib").attr("Path")(path).attr("read_text")();
    py::object geometry;
    try {
      geometry = py::module_::import("json").attr("loads")(text);
    } catch (py::error_already_set &e) {
      if (!e.matches(PyExc_ValueError)) throw;  // json.JSONDecodeError: its line and column
      throw py::value_error(where + ": " + py::str(e.value()).cast<std::string>());
    }
    try {
      return geo_loops(geometry, 0);
    } catch (py::value_error &e) {
      std::string message = e.what();
      throw py::value_error(where + message.substr(message.find(':')));
    }
  }
  py::object mesh =
      import_meshio("read_polygon").attr("read")(path, py::arg("file_format") = meshio_format(path, file_format));
  std::string where = "read_polygon: " + py::str(path).cast<std::string>() + ": ";
  FloatArray points = real_array(mesh.attr("points"), where + "points");
  if (points.ndim() != 2 || (points.shape(1) != 2 && points.shape(1) != 3))
    throw py::value_error(where + "expected n x 2 or n x 3 points, got shape " + shape_of(points));
  std::size_t count = std::size_t(points.shape(0)), dim = std::size_t(points.shape(1));
  std::vector<std::array<std::size_t, 2>> edges;
  for (py::handle block : mesh.attr("cells")) {
    if (py::str(block.attr("type")).cast<std::string>() != "line") continue;
    auto data = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(block.attr("data"));
    for (py::ssize_t i = 0; i < data.shape(0); i++) {
      std::array<std::size_t, 2> edge;
      for (int c = 0; c < 2; c++) {
        std::int64_t p = data.at(i, c);
        if (p < 0 || std::uint64_t(p) >= count)
          throw py::value_error(where + "line " + std::to_string(edges.size()) + " has point " + std::to_string(p) +
                                ", out of range (" + std::to_string(count) + " points)");
        edge[c] = std::size_t(p);
      }
      if (edge[0] == edge[1])
        throw py::value_error(where + "line " + std::to_string(edges.size()) + " joins point " +
                              std::to_string(edge[0]) + " to itself");
      edges.push_back(edge);
    }
  }
  if (edges.empty()) throw py::value_error(where + "no line cells (a polygon is read from its boundary edges)");
  std::vector<std::vector<std::size_t>> at(count);  // the edges at each point
  for (std::size_t e = 0; e < edges.size(); e++)
    for (std::size_t p : edges[e]) at[p].push_back(e);
  for (std::size_t p = 0; p < count; p++)
    if (!at[p].empty() && at[p].size() != 2)
      throw py::value_error(where + "point " + std::to_string(p) + " is on " + std::to_string(at[p].size()) +
                            " lines (a boundary point is on 2)");
  std::vector<bool> used(edges.size(), false);
  std::vector<std::vector<std::size_t>> loops;
  for (std::size_t first = 0; first < edges.size(); first++) {
    if (used[first]) continue;
    std::vector<std::size_t> loop;
    std::size_t point = edges[first][0];
    for (std::size_t e = first; !used[e]; e = at[point][at[point][0] == e ? 1 : 0]) {
      used[e] = true;
      loop.push_back(point);
      point = edges[e][edges[e][0] == point ? 1 : 0];
    }
    loops.push_back(loop);
  }
  const double *xyz = points.data();
  bool planar_xy = true;  // z == 0 everywhere: an n x 2 polygon
  for (const auto &loop : loops)
    for (std::size_t p : loop) planar_xy &= dim == 2 || xyz[3 * p + 2] == 0;
  std::size_t columns = planar_xy ? 2 : 3;
  if (columns == 3 && loops.size() > 1)
    throw py::value_error(where + std::to_string(loops.size()) +
                          " loops out of the z = 0 plane (a polygon with holes is read in the xy plane)");
  auto area = [&](const std::vector<std::size_t> &loop) {
    double twice = 0;
    for (std::size_t i = 0; i < loop.size(); i++) {
      const double *a = xyz + dim * loop[i], *b = xyz + dim * loop[(i + 1) % loop.size()];
      twice += a[0] * b[1] - b[0] * a[1];
    }
    return std::fabs(twice);
  };
  std::size_t outer = 0;
  for (std::size_t l = 1; l < loops.size(); l++)
    if (area(loops[l]) > area(loops[outer])) outer = l;
  std::rotate(loops.begin(), loops.begin() + outer, loops.begin() + outer + 1);
  py::list arrays;
  for (const auto &loop : loops) {
    py::array_t<double> a({py::ssize_t(loop.size()), py::ssize_t(columns)});
    for (std::size_t i = 0; i < loop.size(); i++)
      for (std::size_t c = 0; c < columns; c++) a.mutable_at(i, c) = xyz[dim * loop[i] + c];
    arrays.append(a);
  }
  if (loops.size() == 1) return arrays[0];
  return arrays;
}

// Morph's and sweep's fields by key, as when they were dicts.
template <class T>
void add_mapping(py::class_<T, Output> &cls, const std::vector<std::pair<const char *, const char *>> &fields)
{
  for (const auto &field : fields) {
    std::string key = field.first;
    cls.def_property_readonly(field.first, [key](const T &self) { return py::object(self.fields[key.c_str()]); },
                              field.second);
  }
  cls.def("__getitem__", [](const T &self, const std::string &key) {
        if (!self.fields.contains(key)) throw py::key_error(key);
        return py::object(self.fields[key.c_str()]);
      })
      .def("__contains__", [](const T &self, py::object key) { return self.fields.contains(key); })
      .def("keys", [](const T &self) { return self.fields.attr("keys")(); }, "the field names, as the dict's keys");
}

}  // namespace

PYBIND11_MODULE(compatmesh, m)
{
  m.doc() = "Compatible triangulations of planar polygons whose vertices correspond by index\n"
            "(Surazhsky & Gotsman, High Quality Compatible Triangulations).";
  m.attr("__version__") = std::to_string(CM_VERSION_MAJOR) + "." + std::to_string(CM_VERSION_MINOR) +
                          "." + std::to_string(CM_VERSION_PATCH);

  py::enum_<cm_method>(m, "Method", "How the first compatible triangulation is built.")
      .value("OVERLAY", CM_METHOD_OVERLAY)
      .value("PARTITION", CM_METHOD_PARTITION);
  py::enum_<cm_correspondence>(m, "Correspondence", "Which vertices of the polygons correspond.")
      .value("INDEX", CM_CORRESPOND_INDEX)
      .value("ARCLENGTH", CM_CORRESPOND_ARCLENGTH)
      .value("AUTO", CM_CORRESPOND_AUTO)
      .value("SIMILARITY", CM_CORRESPOND_SIMILARITY);
  py::enum_<cm_smoothing>(m, "Smoothing", "Vertex smoothing in the remesher.")
      .value("LAPLACIAN", CM_SMOOTH_LAPLACIAN)
      .value("ANGLE", CM_SMOOTH_ANGLE)
      .value("WEIGHTED", CM_SMOOTH_WEIGHTED)
      .value("COMBINED", CM_SMOOTH_COMBINED);
  py::enum_<cm_remesher>(m, "Remesher", "How the remesher improves the first compatible triangulation.")
      .value("GREEDY", CM_REMESHER_GREEDY)
      .value("MAP", CM_REMESHER_MAP);

  input_error_type = py::exception<InputErrorTag>(m, "InputError", PyExc_ValueError).inc_ref();
  input_error_type.attr("__doc__") =
      "The input polygons were rejected. str(e) is the core's message; e.status names the\n"
      "reason, e.polygon, e.vertex and e.other_vertex locate it (-1 when not applicable).";
  cancelled_type = py::exception<CancelledTag>(m, "Cancelled", PyExc_Exception).inc_ref();
  cancelled_type.attr("__doc__") = "The progress callback asked to stop.";

  py::class_<Output>(m, "Output", R"doc(What triangulate(), morph() and sweep() return: a Result, a Morph or a Sweep.

Common attributes (arrays are numpy arrays):
  points   the vertex positions: Result, a list of k float64 arrays (nv x 2
           or nv x 3, one per geometry); Morph, F x nv x 2 float64 (one
           section per frame); Sweep, N x 3 float64
  cells    dict from meshio's cell type names to int32 arrays: "triangle"
           (m x 3) for Result and Morph; "wedge" (P x 6, Gmsh's corner order)
           and, with tets, "tetra" (T x 4) for Sweep
  stats    dict: the triangulation's statistics (see Result.stats)
  quality  Result: per geometry a dict of angles; Morph: per frame a dict
           (min_angle_deg, inverted); Sweep: a dict of 3D figures
  to_meshio(...)  a meshio.Mesh (points always nv x 3 float64, z = 0 in the
           plane), or a list of them
  write(path, ..., file_format=None)  one mesh written by meshio (format
           from the extension: .vtu, .vtk, .msh, .xdmf, .obj, .ply, ...))doc")
      .def_readonly("points", &Output::points, "the vertex positions (float64; shape by kind, see Output)")
      .def_readonly("cells", &Output::cells, "dict: meshio cell type name -> int32 array of vertex numbers")
      .def_readonly("stats", &Output::stats, "dict: the triangulation's statistics (see Result.stats)")
      .def_readonly("quality", &Output::quality, "the quality figures (see Output)");

  py::class_<Result, Output>(m, "Result", "A compatible triangulation: one connectivity, k geometries.")
      .def_readonly("faces", &Result::faces, "m x 3 int32 array, counter-clockwise in every geometry")
      .def_readonly("vertices", &Result::vertices,
                    "list of k float64 arrays (n input vertices first, then Steiner vertices), "
                    "each n x 2 or n x 3 like its input")
      .def_readonly("boundary_source", &Result::boundary_source,
                    "per geometry a dict of n arrays: boundary vertex i is the point at t[i] of input edge "
                    "edge[i] -> edge[i] + 1 (t == 0: input vertex edge[i] itself)")
      .def_readonly("halfedges", &Result::halfedges,
                    "dict of int32 arrays: next, to_vertex, face (-1 on the boundary), "
                    "vertex_halfedge, face_halfedge; h ^ 1 is the opposite of h")
      .def_readonly("stats", &Result::stats,
                    "dict: the fields of cm_stats (n, k, vertices, steiner, holes, bridges, holes_moved, pairings_built, "
                    "pairings_remeshed, time_limit_reached, triangles, "
                    "reversed_input, fallback_count, steiner_before_remesh, remesh_iterations, remesh_aim_deg, "
                    "ceiling_deg, corner_fan_cap_deg, correspondence_bound_deg, modulus_distortion, "
                    "distortion_quad, correspondence_bound_before_deg (None unless auto chose the starts), "
                    "correspondence_choice (the correspondence made: 'index', 'arclength', 'conformal', "
                    "'similarity', 'affine', 'corners' or 'annulus'; with holes the outer loop's), "
                    "seconds_*), quality and quality_before_remesh (one dict per geometry)")
      .def("to_meshio", &result_to_meshio, py::arg("geometry") = py::none(),
           R"doc(to_meshio(geometry=None) -> meshio.Mesh or list of meshio.Mesh

Geometry g (0 to k-1, negative from the end) as a meshio.Mesh: points
nv x 3 float64 (z = 0 for planar input), cells [("triangle", m x 3 int32)];
without geometry, a list of the k meshes. Needs meshio.)doc")
      .def(
          "write",
          [](const Result &r, py::object path, py::object geometry, py::object file_format) {
            write_mesh(result_to_meshio(r, the_one(geometry, py::len(r.vertices), "geometry")), path,
                       meshio_format(path, file_format));
          },
          py::arg("path"), py::arg("geometry") = py::none(), py::arg("file_format") = py::none(),
          R"doc(write(path, geometry, file_format=None)

Writes to_meshio(geometry) with meshio.write: the format from the path's
extension unless file_format names one of meshio's; .msh is Gmsh's (text,
format 4.1).)doc")
      .def("__repr__", [](const Result &r) {
        return "<compatmesh.Result: " + py::str(r.stats["k"]).cast<std::string>() + " geometries, " +
               py::str(r.stats["vertices"]).cast<std::string>() + " vertices, " +
               py::str(r.stats["triangles"]).cast<std::string>() + " triangles>";
      });

  py::class_<Morph, Output> morph_class(m, "Morph", R"doc(Sections of the morph through compatibly triangulated polygons.

Fields, as attributes and by key (m["sections"]):
  faces          m x 3 int32, the same in every section, counter-clockwise
  t              F float64, the times
  sections       F x nv x 2 float64, the n polygon vertices first
  inverted       F int64, triangles not strictly counter-clockwise
  min_angle_deg  F float64, the smallest angle of each section
  n              int, the number of polygon vertices)doc");
  add_mapping(morph_class, {{"faces", "m x 3 int32 array, the same in every section"},
                            {"t", "F float64 array: the times of the sections"},
                            {"sections", "F x nv x 2 float64 array, the n polygon vertices first"},
                            {"inverted", "F int64 array: triangles not strictly counter-clockwise"},
                            {"min_angle_deg", "F float64 array: each section's smallest angle"},
                            {"n", "int: the number of polygon vertices"}});
  morph_class
      .def("to_meshio", &morph_to_meshio, py::arg("frame") = py::none(),
           R"doc(to_meshio(frame=None) -> meshio.Mesh or list of meshio.Mesh

Section `frame` (0 to F-1, negative from the end) as a meshio.Mesh: points
nv x 3 float64 (z = 0), cells [("triangle", m x 3 int32)]; without frame, a
list of the F meshes. Needs meshio.)doc")
      .def(
          "write",
          [](const Morph &mo, py::object path, py::object frame, py::object file_format) {
            py::ssize_t frames = py::array::ensure(mo.fields["sections"]).shape(0);
            write_mesh(morph_to_meshio(mo, the_one(frame, (size_t)frames, "frame")), path,
                       meshio_format(path, file_format));
          },
          py::arg("path"), py::arg("frame") = py::none(), py::arg("file_format") = py::none(),
          R"doc(write(path, frame, file_format=None)

Writes to_meshio(frame) with meshio.write: the format from the path's
extension unless file_format names one of meshio's; .msh is Gmsh's (text,
format 4.1).)doc")
      .def("__repr__", [](const Morph &mo) {
        py::array sections = py::array::ensure(mo.fields["sections"]);
        return "<compatmesh.Morph: " + std::to_string(sections.shape(0)) + " frames, " +
               std::to_string(sections.shape(1)) + " vertices, " + std::to_string(py::len(mo.fields["faces"])) +
               " triangles>";
      });

  py::class_<Sweep, Output> sweep_class(m, "Sweep", R"doc(The volume swept between compatibly triangulated polygons.

Fields, as attributes and by key (s["nodes"]):
  nodes        N x 3 float64; node s * nv + v is vertex v of section s
  prisms       P x 6 int32, Gmsh's wedge order (bottom counter-clockwise
               seen from +z, then the top)
  tets         T x 4 int32, positive volume (0 x 4 without tets)
  section_z    S float64, the sections' heights
  volume, height (floats), height_is_default (bool)
  morph        "convex", "intrinsic" where the convex morph needed
               more inserted sections than max_refine, or "linear" for
               a ruled sweep
  quality      dict of 3D figures (see sweep()))doc");
  add_mapping(sweep_class, {{"nodes", "N x 3 float64 array; node s * nv + v is vertex v of section s"},
                            {"prisms", "P x 6 int32 array, Gmsh's wedge order"},
                            {"tets", "T x 4 int32 array, positive volume (0 x 4 without tets)"},
                            {"section_z", "S float64 array: the sections' heights"},
                            {"volume", "float: the prisms' total volume"},
                            {"height", "float: first to last section"},
                            {"height_is_default", "bool: the height came from the polygons' size"},
                            {"morph", "str: the morph whose sections were stacked: convex, intrinsic, or linear (ruled)"}});
  sweep_class
      .def("to_meshio", &sweep_to_meshio, py::arg("cells") = py::none(),
           R"doc(to_meshio(cells=None) -> meshio.Mesh

The sweep as a meshio.Mesh: points N x 3 float64 (the nodes), cells
[("tetra", T x 4 int32)] for cells="tetra" (the default when the sweep has
tetrahedra) or [("wedge", P x 6 int32)] for cells="wedge" (the default
otherwise), the prisms in meshio's (VTK's) corner order: a, c, b, d, f, e
of Gmsh's a, b, c, d, e, f. Needs meshio.)doc")
      .def(
          "write",
          [](const Sweep &sw, py::object path, py::object cells, py::object file_format, int order) {
            py::object format = meshio_format(path, file_format);
            std::string f = format.is_none() ? "" : std::string(py::str(format));
            bool tets = sweep_tets(sw, cells, "write");
            if (order != 1 && order != 2) throw py::value_error("write: order must be 1 or 2");
            // the formats Gmsh writes, by the extension it goes by
            static const std::pair<const char *, const char *> gmsh_formats[] = {
                {"gmsh", ".msh"}, {"gmsh22", ".msh"}, {"abaqus", ".inp"}, {"nastran", ".bdf"}, {"vtk", ".vtk"}};
            const char *extension = nullptr;
            for (const auto &known : gmsh_formats)
              if (f == known.first) extension = known.second;
            if (order == 2 && !extension)
              throw py::value_error("write: second-order cells (order=2) go to the formats Gmsh writes: .msh, "
                                    ".inp, .bdf, .vtk");
#ifdef CM_PYTHON_HAVE_GMSH
            if (f == "gmsh" || f == "gmsh22" || order == 2) {
              // the temporary name ends in the extension Gmsh goes by
              std::string title = py::str(py::module_::import("pathlib").attr("Path")(path).attr("name"));
              write_atomically(path, false, extension, [&](py::object written) {
                write_sweep_gmsh(sw, tets, py::str(written), f == "gmsh22" ? 2.2 : 4.1, order, title);
              });
              return;
            }
#else
            if (order == 2)
              throw std::runtime_error("write: second-order cells (order=2) need Gmsh, and this compatmesh was "
                                       "built without it");
#endif
            py::object mesh = sweep_mesh(sw, cells, gmsh_wedge_order(format), "write");
            if (f != "abaqus") return write_mesh(mesh, path, format);
            // as the command line's deck: the cells in ELSET sweep, the
            // boundary's groups as node sets and element-face surfaces
            py::dict cell_sets;
            cell_sets["sweep"] = py::make_tuple(py::module_::import("numpy").attr("arange")(
                py::len(sw.fields[tets ? "tets" : "prisms"])));
            mesh.attr("cell_sets") = cell_sets;
            write_mesh(mesh, path, format, [&](const std::string &file) { append_abaqus_sets(sw, tets, file); });
          },
          py::arg("path"), py::arg("cells") = py::none(), py::arg("file_format") = py::none(), py::arg("order") = 1,
          R"doc(write(path, cells=None, file_format=None, order=1)

Writes the sweep's cells (to_meshio(cells)), the format from the path's
extension unless file_format names one of meshio's. .msh (file_format
"gmsh", or "gmsh22" for version 2.2) is written by Gmsh itself, as the
command line writes it: text format 4.1, the cells in the physical group
"sweep" and the boundary as surfaces with a physical group each (see
boundary()). Abaqus's .inp gets the boundary's groups as node sets
(*NSET) and element-face surfaces (*SURFACE, TYPE=ELEMENT, for *DSLOAD).
order=2 writes second-order cells (a node at the middle of every edge,
straight-sided: 10-node tetrahedra, 15-node prisms, Abaqus C3D10 and
C3D15) through Gmsh, as `compatmesh sweep --order 2` does, to .msh,
.inp, .bdf or .vtk. The other formats go through meshio.write with the cells only;
Abaqus's and Nastran's get the prisms in their own corner order (Gmsh's),
the others VTK's.)doc")
      .def("boundary", &sweep_boundary, py::arg("cells") = py::none(),
           R"doc(boundary(cells=None) -> dict

The volume's boundary, for boundary conditions: group name -> int32 faces
(node indices), in this order: "bottom" (the first polygon's section),
"top" (the last), "side" (the wall over the outer loop), "hole_1",
"hole_2", ... (the wall over each hole). Caps are k x 3 triangles; the
walls are the prisms' side quads (k x 4: a, b, b', a', where a -> b is a
boundary edge and primes are one section up) or, for cells="tetra" (the
default when the sweep has tetrahedra), the k x 3 triangles of the
tetrahedra's faces there. Every face is ordered so that its normal
(right-hand rule) points out of the volume.)doc")
      .def("boundary_cells", &sweep_boundary_cells, py::arg("cells") = py::none(),
           R"doc(boundary_cells(cells=None) -> dict

Which cell face each face of boundary(cells) is, for solvers that load
element faces (an Abaqus or CalculiX *SURFACE, TYPE=ELEMENT): group name
-> k x 2 int64, the cell's row in prisms (cells="wedge") or tets
(cells="tetra") and its face, numbered as Abaqus numbers them from S1,
here from 0. Prisms (corners a b c over a' b' c', the order of prisms):
0 the bottom, 1 the top, 2 + j the quad over the triangle's edge j
(a b, b c, c a); tetrahedra (corners 1 to 4): 0 1-2-3, 1 1-4-2, 2 2-4-3,
3 3-4-1. cm_sweep_boundary_cells in the C API.)doc")
      .def("__repr__", [](const Sweep &sw) {
        return "<compatmesh.Sweep: " + std::to_string(py::len(sw.fields["nodes"])) + " nodes, " +
               std::to_string(py::len(sw.fields["prisms"])) + " prisms, " +
               std::to_string(py::len(sw.fields["tets"])) + " tetrahedra>";
      });

  m.def("read_polygon", &read_polygon_file, py::arg("path"), py::arg("file_format") = py::none(),
        R"doc(read_polygon(path, file_format=None) -> array or list of arrays

A polygon from any file meshio reads (.vtk, .vtu, .msh, ...; the format from
the extension unless file_format names one of meshio's), given by its
boundary: the file's "line" cells, chained into closed loops (every point on
a line is on exactly two). One loop: an n x 2 float64 array (n x 3 when some
z is not 0), the points in the order of the lines from the first line of the
file. Several loops: a list of n_j x 2 float64 arrays, the loop of largest
area first, then the holes in file order, as triangulate() takes a polygon
with holes. Raises ValueError naming the file and the line or point at
fault. Needs meshio. A .geojson or .json file is read as GeoJSON (a
Polygon, alone, in a Feature or in a FeatureCollection of one Feature):
its rings without their closing repeat, n x 2 (n x 3 with z), the exterior
first.)doc");

  m.def("triangulate", &triangulate, py::arg("polygons"),
        R"doc(triangulate(polygons, **options) -> Result

Compatibly triangulates k >= 2 simple polygons, with or without holes: one
triangle list that is a valid triangulation of every polygon. Vertices
correspond by index (the default for equal counts), or by arc length or
the automatic choice, which add the other polygons' points on each
polygon's edges (correspondence below).

polygons: a sequence of k arrays, each n x 2, or n x 3 for a polygon in any
    plane of 3D (fitted by least squares and mapped to 2D and back; the
    normal points to +x, +y or +z, whichever it is closest to, so the winding
    is kept). A polygon with holes is a list of n_j x 2 arrays, the outer
    loop first, then the holes; every polygon then has the same number of
    loops of the same sizes (loop j corresponds to loop j, vertex by index),
    and the result's vertices are the loops' vertices in that order, then
    the Steiner vertices. A polygon may also be a GeoJSON Polygon (a dict,
    or any object with __geo_interface__: shapely, geopandas, fiona): its
    exterior ring, then its holes, each ring without its closing repeat.
options: keyword arguments named like the fields of the C struct cm_options,
    defaults from cm_options_init (see compatmesh.h for their meaning):
    method          compatmesh.Method, its int value, or "overlay" / "partition"
    remesh          bool: improve the triangles (default True)
    min_angle_deg   target smallest angle in degrees
    max_steiner     most Steiner vertices the refinement may add (-1: automatic)
    k_split, area_every, max_iterations, restarts   ints, see compatmesh.h
    ceiling         bool: compute the certified caps on the smallest angle
                    (stats ceiling_deg ...; the remesher aims no higher);
                    default True, False for the fastest run
    smoothing       compatmesh.Smoothing, its int value, or "laplacian" /
                    "angle" / "weighted" / "combined"
    remesher        compatmesh.Remesher, its int value, or "greedy" (the
                    default) / "map" (lower the maps' distortion and refine
                    in the metric halfway between the polygons first)
    progress        callable(fraction, stage); return True to cancel
    correspondence  "index" (vertex i is vertex i; equal counts; the default
                    when the counts are equal) or "arclength" (normalised
                    arc length between pins; each polygon keeps its vertices
                    and gets the others' on its edges; the default with
                    pins), "auto" (the default when the counts differ;
                    output as arclength: conformal, the polygons' maps onto
                    the disk made to agree (where turns fit alike, as a
                    disc's, the one that puts holes on holes and turns
                    least), their crowding tempered; with
                    holes the outer loops so, the holes paired by position
                    where that is one-to-one (stats["holes_moved"]), every
                    hole from the start nearest, carried radially through
                    the outer loops; with
                    pin_corners_deg, arc length from the starts that
                    align the polygons best up to a similarity),
                    "similarity" (that alignment for all polygons), or a
                    compatmesh.Correspondence
    pins            arclength: a sequence of tuples, one vertex per polygon,
                    that correspond (default: the first vertices)
    pin_corners_deg pin every vertex whose corner angle deviates from 180
                    degrees by more than this, in order (see compatmesh.h for
                    different corner counts); 0 (default): off
    max_edge        split the boundary edges compatibly until none is longer
                    than this in any polygon (each keeps its vertices; also
                    with "index"); 0 (default): off
    time_limit      CPU seconds after which the remesher stops at its next
                    safe point and the result reached is returned
                    (stats["time_limit_reached"]); 0 (default): no limit
  and planarity_tolerance: how far a 3D point may lie from the plane, as a
    fraction of the polygon's bounding-box diagonal (default 1e-5).
Returns a Result: faces (m x 3 int32), vertices (= points; a list of k
float64 arrays, nv x 2 or nv x 3 like the input), boundary_source,
halfedges, stats, quality (per geometry), cells ({"triangle": faces}),
to_meshio(geometry) and write(path, geometry).
Raises InputError (a ValueError) with the core's message for bad input,
TypeError for an unknown keyword, Cancelled when progress asked to stop,
RuntimeError if the construction failed its own check.)doc");

  m.def("morph", &morph, py::arg("polygons"), py::arg("t") = py::none(), py::arg("frames") = py::none(),
        py::arg("morph_method") = "convex",
        R"doc(morph(polygons, t=None, frames=None, morph_method="convex", **options) -> Morph

Triangulates the n x 2 polygons as triangulate() does (same keyword options)
and returns sections of the morph through them: the polygons are surrounded
by a common convex enclosure and every interior vertex is a convex
combination of its neighbours (Floater-Gotsman), so every section of the
"convex" morph is a valid triangulation; "linear" moves the vertices on
straight lines, for comparison (its inverted triangles are counted). With
k > 2 polygons the morph passes through polygon g at t = g / (k - 1).
Polygons given n x 3 in planes that are not all z = constant (sections in
space) are placed as sweep() places a loft's, and each section is in
space: at a polygon's time its vertices as triangulate() gives them, in
between each vertex blended between its points in the planes of the two
polygons around t (sections F x nv x 3). Polygons given n x 3 in planes
z = constant morph as their (x, y) do, each section at the z blended
between the planes around t, as sweep()'s layers (sections F x nv x 3).

t: a time in [0, 1] or a sequence of them; or frames: a count >= 2 of evenly
    spaced times from 0 to 1 (give exactly one).
Returns a Morph (its fields also by key, as in a dict): faces (m x 3 int32,
the same in every section), t (F float64), sections (F x nv x 2 float64, or
F x nv x 3 for polygons given n x 3, the n polygon vertices first), inverted (F int64: triangles not strictly
counter-clockwise, by exact predicates), min_angle_deg (F float64), n; and
points (= sections), cells, stats (the triangulation's), quality (per
frame), to_meshio(frame), write(path, frame). Raises InputError (a ValueError) for bad polygons, ValueError with
the core's message for a bad t, RuntimeError if a convex section failed its
exact check.)doc");

  m.def("sweep", &sweep, py::arg("polygons"), py::arg("sections") = 11, py::arg("height") = py::none(),
        py::arg("heights") = py::none(), py::arg("tets") = false, py::arg("wall_corner_deg") = 0.0,
        py::arg("ruled") = false,
        R"doc(sweep(polygons, sections=11, height=None, heights=None, tets=False, wall_corner_deg=0, ruled=False, **options) -> Sweep

The volume between the n x 2 polygons: sections of their convex morph
stacked at increasing z and joined into 6-node prisms, each checked exactly
to stay valid through its height (sections are inserted where needed).
Polygon g lies at heights[g] (strictly increasing), or the polygons are
evenly spaced over height (default: the largest diagonal of the polygons'
bounding boxes). Polygons given n x 3 in planes z = constant (slices of a
model) lie at their own z unless height or heights is given. Polygons given
n x 3 in other planes (sections of a bent part, listed the same way round
along it) are lofted between their planes: the sweep is built with heights
the distances between the sections' centres (the mean of their vertices;
section_z, height), and every
node is then placed between the planes of the polygons around it, each cell
checked positive in space, exactly (ValueError where the straight blend
between two planes folds: planes too close for their turn or crossing
inside the polygons, or a polygon listed the other way round); height and
heights are then refused. sections: per pair of consecutive
polygons, both ends included, 2 to 10000, or "auto": layers about as tall
as the triangulation's median edge in the tallest pair, prisms about as
tall as wide (`--sections auto`). tets: also split every prism into 3
tetrahedra with conforming faces. wall_corner_deg: split the boundary's
walls (boundary()) at the corners where a polygon's boundary turns by more
than this many degrees (0, the default: one wall per loop). ruled: a
ruled sweep, as a CAD loft (every vertex on a straight line between
consecutive polygons, the walls ruled surfaces) where every prism stays
valid along it, checked exactly; else the convex morph's sections (morph
says which: "linear" for the ruled sweep). Keyword options as for
triangulate().
Returns a Sweep (its fields also by key, as in a dict): nodes (N x 3 float64;
node s * nv + v is vertex v of section s), prisms (P x 6 int32, Gmsh wedge
order: bottom counter-clockwise seen from +z, then top), tets (T x 4 int32,
positive volume; 0 x 4 unless tets), section_z (S float64), volume (the prisms' total), height (first to last section) and
height_is_default, morph ("convex", "intrinsic" where the convex morph
needed more sections than max_refine, "linear" for a ruled sweep), quality (a dict for the tetrahedra if tets, else the
prisms: min_dihedral_deg, max_dihedral_deg, min_scaled_jacobian,
max_aspect_ratio, max_prism_flatness = longest triangle edge / prism height,
flat_prisms = prisms flatter than 1:10); and points (= nodes), cells,
stats (the triangulation's), to_meshio(cells), write(path). Bad arguments
raise ValueError with the core's message.)doc");
}
