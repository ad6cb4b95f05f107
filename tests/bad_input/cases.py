"""Reader for tests/bad_input/cases.txt (format described there), for the
Python-side tests: the CLI's and the Python module's."""
import os
from dataclasses import dataclass, field

PATH = os.path.join(os.path.dirname(os.path.abspath(__file__)), "cases.txt")


@dataclass
class Case:
    name: str
    status: str              # cm_status_string of the expected status
    polygon: object          # int, or None when not checked
    vertex: object
    fragment: str
    polygons: list = field(default_factory=list)  # lists of (x, y)


def _location(text):
    return None if text in ("*", "-") else int(text)


def load(path=PATH):
    cases = []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            if line.startswith("case "):
                name, status, where, fragment = (p.strip() for p in line[5:].split("|"))
                polygon, vertex = where.split()
                cases.append(Case(name, status, _location(polygon), _location(vertex), fragment))
            elif line.startswith("poly "):
                values = [float(v) for v in line[5:].split()]
                cases[-1].polygons.append(list(zip(values[0::2], values[1::2])))
            else:
                raise ValueError(f"{path}:{number}: malformed bad-input case")
    return cases
