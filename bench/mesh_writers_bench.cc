// The tool's hand-written OFF/OBJ/PLY writers (cli/write_mesh.c, numbers by
// cli/format_double.h) against OpenMesh's writers of the same formats, on
// the same triangle mesh written REPEATS times (a morph writes one mesh per
// frame): CPU time per write, bytes, and whether every coordinate reads
// back bit for bit. OpenMesh writes ASCII with the precision argument of
// IO::write_mesh (17 digits: the fewest that always read back) and binary
// with IO::Options::Binary.
//   cm_mesh_writers_bench MESH.off WORK_DIR [REPEATS]
// MESH.off: an OFF file of triangles, e.g. a frame `compatmesh morph` wrote.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include <sys/stat.h>

extern "C" {
#include "interrupt.h"
#include "write_mesh.h"
}

// outdir.c's flags, which interrupt.c (the tool's signal handling) defines.
volatile sig_atomic_t interrupted, writing_output;

namespace {

struct DoubleTraits : OpenMesh::DefaultTraits {
    typedef OpenMesh::Vec3d Point;
};
typedef OpenMesh::TriMesh_ArrayKernelT<DoubleTraits> Mesh;

struct Triangles {
    std::vector<double> xy; // 2 per vertex
    std::vector<int32_t> triangles;
    size_t vertices() const { return xy.size() / 2; }
};

[[noreturn]] void fail(const std::string &message)
{
    std::fprintf(stderr, "cm_mesh_writers_bench: %s\n", message.c_str());
    std::exit(1);
}

std::string read_text(const std::string &path)
{
    FILE *file = std::fopen(path.c_str(), "rb");
    if (!file) fail("cannot read " + path + ": " + std::strerror(errno));
    std::string text;
    char buffer[1 << 16];
    size_t got;
    while ((got = std::fread(buffer, 1, sizeof buffer, file)) > 0) text.append(buffer, got);
    std::fclose(file);
    return text;
}

// "OFF\nV F 0\n" then V lines "x y z" and F lines "3 a b c".
Triangles read_off(const std::string &path)
{
    std::string text = read_text(path);
    const char *at = text.c_str();
    char *end;
    if (std::strncmp(at, "OFF", 3) != 0) fail(path + ": not an OFF file");
    at += 3;
    long vertices = std::strtol(at, &end, 10), faces = std::strtol(end, &end, 10);
    std::strtol(end, &end, 10);
    if (vertices < 3 || faces < 1) fail(path + ": no triangles");
    Triangles mesh;
    for (long i = 0; i < vertices; i++) {
        mesh.xy.push_back(std::strtod(end, &end));
        mesh.xy.push_back(std::strtod(end, &end));
        std::strtod(end, &end);
    }
    for (long f = 0; f < faces; f++) {
        if (std::strtol(end, &end, 10) != 3) fail(path + ": a face is not a triangle");
        for (int k = 0; k < 3; k++) mesh.triangles.push_back((int32_t)std::strtol(end, &end, 10));
    }
    return mesh;
}

double cpu_seconds()
{
    timespec now;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
    return (double)now.tv_sec + 1e-9 * (double)now.tv_nsec;
}

uint64_t bits_of(double x)
{
    uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    return bits;
}

// Every vertex line of an ASCII file, "[v ]x y z", read with strtod and
// compared with the mesh's x, y and z = 0.
bool ascii_exact(const std::string &path, const Triangles &mesh, int header_lines, const char *prefix)
{
    std::string text = read_text(path);
    const char *at = text.c_str();
    for (int skipped = 0; skipped < header_lines; skipped++) at = std::strchr(at, '\n') + 1;
    for (size_t i = 0; i < mesh.vertices(); i++) {
        while (*at == '#' || *at == '\n') at = std::strchr(at, '\n') + 1; // OpenMesh's comments
        if (prefix) {
            if (std::strncmp(at, prefix, std::strlen(prefix)) != 0) return false;
            at += std::strlen(prefix);
        }
        char *end;
        double x = std::strtod(at, &end), y = std::strtod(end, &end), z = std::strtod(end, &end);
        if (bits_of(x) != bits_of(mesh.xy[2 * i]) || bits_of(y) != bits_of(mesh.xy[2 * i + 1]) ||
            bits_of(z) != bits_of(0.0))
            return false;
        at = std::strchr(end, '\n');
        if (!at) return false;
        at++;
    }
    return true;
}

// A binary little-endian PLY: "property double x/y/z" and the vertices'
// doubles right after end_header.
bool binary_ply_exact(const std::string &path, const Triangles &mesh)
{
    std::string text = read_text(path);
    size_t header_end = text.find("end_header\n");
    if (header_end == std::string::npos || text.find("property double x") > header_end) return false;
    const char *data = text.data() + header_end + std::strlen("end_header\n");
    for (size_t i = 0; i < mesh.vertices(); i++) {
        double xyz[3];
        std::memcpy(xyz, data + 24 * i, sizeof xyz);
        if (bits_of(xyz[0]) != bits_of(mesh.xy[2 * i]) || bits_of(xyz[1]) != bits_of(mesh.xy[2 * i + 1]))
            return false;
    }
    return true;
}

// Any other binary file: read back by OpenMesh into double points.
bool openmesh_readback_exact(const std::string &path, const Triangles &mesh, OpenMesh::IO::Options options)
{
    Mesh back;
    if (!OpenMesh::IO::read_mesh(back, path, options) || back.n_vertices() != mesh.vertices()) return false;
    for (size_t i = 0; i < mesh.vertices(); i++) {
        Mesh::Point p = back.point(back.vertex_handle((unsigned)i));
        if (bits_of(p[0]) != bits_of(mesh.xy[2 * i]) || bits_of(p[1]) != bits_of(mesh.xy[2 * i + 1])) return false;
    }
    return true;
}

// Lines of a PLY header, end_header included.
int ply_header_lines(const std::string &path)
{
    std::string text = read_text(path);
    size_t end = text.find("end_header\n");
    return end == std::string::npos ? 0 : (int)std::count(text.begin(), text.begin() + (long)end, '\n') + 1;
}

long file_size(const std::string &path)
{
    struct stat info;
    return stat(path.c_str(), &info) == 0 ? (long)info.st_size : -1;
}

struct Writer {
    std::string name, file;
    bool ours;
    mesh_format format;          // ours
    OpenMesh::IO::Options options; // OpenMesh
    double seconds = 0;
};

} // namespace

int main(int argc, char **argv)
{
    if (argc < 3 || argc > 4) {
        std::fputs("usage: cm_mesh_writers_bench MESH.off WORK_DIR [REPEATS]\n", stderr);
        return 2;
    }
    omlog().disable(); // "[OBJWriter] : write file" at every write
    Triangles mesh = read_off(argv[1]);
    std::string dir = argv[2];
    int repeats = argc == 4 ? std::atoi(argv[3]) : 100;
    if (repeats < 1) fail("REPEATS must be at least 1");
    mkdir(dir.c_str(), 0777);

    // OpenMesh needs its own mesh: built once (a morph would only move the
    // points between frames), its cost reported apart.
    double start = cpu_seconds();
    Mesh om;
    std::vector<Mesh::VertexHandle> handles;
    for (size_t i = 0; i < mesh.vertices(); i++)
        handles.push_back(om.add_vertex(Mesh::Point(mesh.xy[2 * i], mesh.xy[2 * i + 1], 0.0)));
    for (size_t t = 0; t < mesh.triangles.size(); t += 3)
        om.add_face(handles[mesh.triangles[t]], handles[mesh.triangles[t + 1]], handles[mesh.triangles[t + 2]]);
    double build_seconds = cpu_seconds() - start;
    if (om.n_faces() * 3 != mesh.triangles.size()) fail("OpenMesh refused some triangles");

    OpenMesh::IO::Options ascii, binary(OpenMesh::IO::Options::Binary);
    std::vector<Writer> writers = {
        {"compatmesh OFF", "ours.off", true, MESH_FORMAT_OFF, ascii},
        {"compatmesh OBJ", "ours.obj", true, MESH_FORMAT_OBJ, ascii},
        {"compatmesh PLY", "ours.ply", true, MESH_FORMAT_PLY, ascii},
        {"OpenMesh OFF, precision 17", "om.off", false, MESH_FORMAT_OFF, ascii},
        {"OpenMesh OBJ, precision 17", "om.obj", false, MESH_FORMAT_OBJ, ascii},
        {"OpenMesh PLY, precision 17", "om.ply", false, MESH_FORMAT_PLY, ascii},
        {"OpenMesh PLY binary", "om_binary.ply", false, MESH_FORMAT_PLY, binary},
        {"OpenMesh OFF binary", "om_binary.off", false, MESH_FORMAT_OFF, binary},
    };
    // Interleaved: each round writes with every writer once.
    for (int round = 0; round < repeats; round++) {
        for (Writer &w : writers) {
            std::string path = dir + "/" + w.file;
            double t0 = cpu_seconds();
            bool ok;
            if (w.ours) {
                cli_error error;
                ok = write_triangle_mesh(path.c_str(), mesh.xy.data(), nullptr, mesh.vertices(), mesh.triangles.data(),
                                         mesh.triangles.size() / 3, w.format, &error) == CLI_EXIT_OK;
            } else {
                ok = OpenMesh::IO::write_mesh(om, path, w.options, 17);
            }
            w.seconds += cpu_seconds() - t0;
            if (!ok) fail("cannot write " + path);
        }
    }

    std::printf("%zu vertices, %zu triangles, %d writes each; OpenMesh mesh built in %.2f ms\n\n",
                mesh.vertices(), mesh.triangles.size() / 3, repeats, 1e3 * build_seconds);
    std::printf("| writer | ms per write | bytes | bit-exact |\n|---|---:|---:|---|\n");
    for (const Writer &w : writers) {
        std::string path = dir + "/" + w.file;
        bool exact;
        if (w.options.check(OpenMesh::IO::Options::Binary))
            exact = w.format == MESH_FORMAT_PLY ? binary_ply_exact(path, mesh)
                                                : openmesh_readback_exact(path, mesh, w.options);
        else if (w.format == MESH_FORMAT_OFF)
            exact = ascii_exact(path, mesh, 2, nullptr);
        else if (w.format == MESH_FORMAT_OBJ)
            exact = ascii_exact(path, mesh, w.ours ? 1 : 0, "v ");
        else
            exact = ascii_exact(path, mesh, ply_header_lines(path), nullptr);
        std::printf("| %s | %.3f | %ld | %s |\n", w.name.c_str(), 1e3 * w.seconds / repeats, file_size(path),
                    exact ? "yes" : "NO");
    }
    return 0;
}
