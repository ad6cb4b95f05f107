// The MeshLab sweep dialog's default layers: the pair the triangulation
// filter added last, whatever the current layer and the older layers are.
#include "default_layers.h"

#include <cstdio>

using compatmesh_plugin::LayerCounts;

static int failures = 0;

static void expect(const std::vector<LayerCounts> &layers, bool found, std::size_t first, std::size_t second,
                   const char *what)
{
  std::size_t a = 99, b = 99;
  bool got = compatmesh_plugin::newest_compatible_pair(layers, a, b);
  if (got != found || (found && (a != first || b != second))) {
    std::printf("FAILED %s: got %d (%zu, %zu)\n", what, int(got), a, b);
    failures++;
  }
}

int main()
{
  // Two input polylines (no faces), then the pair the filter added.
  expect({{12, 0}, {12, 0}, {14, 16}, {14, 16}}, true, 2, 3, "the pair after two polylines");
  // A second pairing later: its layers, not the first pair's.
  expect({{12, 0}, {12, 0}, {14, 16}, {14, 16}, {30, 0}, {30, 0}, {40, 50}, {40, 50}}, true, 6, 7, "the newest pair");
  // A newer unrelated layer with faces (a section) between: still a pair of equal counts.
  expect({{14, 16}, {14, 16}, {5, 3}}, true, 0, 1, "an unmatched newer layer is skipped");
  // Polylines only, or a single disk: no pair.
  expect({{12, 0}, {12, 0}}, false, 0, 0, "polylines only");
  expect({{14, 16}}, false, 0, 0, "one disk");
  std::printf("test_default_layers: %d failed\n", failures);
  return failures ? 1 : 0;
}
