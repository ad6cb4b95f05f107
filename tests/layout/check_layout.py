"""The library's shape, read from what the compiler made (binutils' nm):

- the shared library exports the public API only: its defined dynamic
  symbols are exactly the functions compatmesh.h marks CM_API;
- no two of the core's source files call each other, directly or through
  others: the graph "file A uses a function defined in file B" has no cycle,
  so every stage only calls down.

usage: check_layout.py COMPATMESH_H SHARED_LIBRARY OBJECT...
"""
import os
import re
import subprocess
import sys


def symbols(path, *flags):
    out = subprocess.run(["nm", *flags, path], check=True, capture_output=True, text=True).stdout
    for line in out.splitlines():
        parts = line.split()
        if len(parts) >= 2:
            yield parts[-2], parts[-1]  # type, name


def exported(library):
    return sorted(name for kind, name in symbols(library, "-D", "--defined-only") if kind in "TDBRVW")


def api_functions(header):
    text = open(header, encoding="utf-8").read()
    return sorted(set(re.findall(r"^CM_API\b[^;(]*?\b(cm_\w+)\(", text, re.M)))


def call_graph(objects):
    """file -> files whose functions or data it uses."""
    defined, used = {}, {}
    for path in objects:
        name = os.path.basename(path).removesuffix(".o").removesuffix(".c")
        used[name] = set()
        for kind, symbol in symbols(path):
            if kind == "U":
                used[name].add(symbol)
            elif kind in "TDBR":
                defined[symbol] = name
    return {f: {defined[s] for s in syms if s in defined and defined[s] != f} for f, syms in used.items()}


def find_cycle(graph):
    state, stack = {}, []

    def visit(node):
        state[node] = 1
        stack.append(node)
        for nxt in sorted(graph.get(node, ())):
            if state.get(nxt) == 1:
                return stack[stack.index(nxt):] + [nxt]
            if nxt not in state:
                cycle = visit(nxt)
                if cycle:
                    return cycle
        stack.pop()
        state[node] = 2
        return None

    for node in sorted(graph):
        if node not in state:
            cycle = visit(node)
            if cycle:
                return cycle
    return None


def main(argv):
    if len(argv) < 4:
        print(__doc__, file=sys.stderr)
        return 2
    header, library, objects = argv[1], argv[2], argv[3:]
    failures = 0
    api, names = api_functions(header), exported(library)
    extra, missing = sorted(set(names) - set(api)), sorted(set(api) - set(names))
    if extra or missing or not api:
        print(f"FAIL: {library} exports {len(extra)} symbols outside the API ({' '.join(extra[:12])}) "
              f"and misses {len(missing)} of it ({' '.join(missing[:12])})")
        failures += 1
    else:
        print(f"ok: {library} exports exactly the {len(api)} API functions")
    graph = call_graph(objects)
    cycle = find_cycle(graph)
    if cycle:
        print("FAIL: source files call each other in a loop: " + " -> ".join(cycle))
        failures += 1
    else:
        print(f"ok: {len(graph)} source files, no call cycle")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
