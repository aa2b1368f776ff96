"""Checks that the layers of src/ include each other in one direction only
(README, "Layout"), and that the statistical layer includes no FE code: no
deal.II header beyond deal.II/base and none of src/fe.  Usage: check_layering.py SRC"""
import pathlib
import re
import sys

src = pathlib.Path(sys.argv[1])
# What each layer may include besides itself.
allowed = {
    "input": [],
    "parallel": ["input/input_error.h"],
    "fe": ["input", "parallel"],
    "fracture": ["input", "parallel", "fe"],
    "fourier": [],
    "contact": ["fourier"],
    "statistics": ["input/input_error.h", "parallel", "fourier", "fracture/adhesive_gap.h"],
    "output": ["input", "parallel", "fe", "fracture"],
    "scenes": ["input", "parallel", "fe", "fracture", "fourier", "contact", "statistics", "output"],
    "apps": ["input", "scenes"],
}
fe_free = {"input", "parallel", "fourier", "contact", "statistics"}  # no deal.II beyond deal.II/base
problems = []
for path in sorted(src.rglob("*.[ch]*")):
    layer = path.relative_to(src).parts[0]
    for line in path.read_text().splitlines():
        own = re.match(r'#include "([^"]+)"', line)
        if own:
            target = own.group(1)
            if not (target.startswith(layer + "/") or any(target == a or target.startswith(a + "/") for a in allowed[layer])):
                problems.append(f"{path.relative_to(src)} includes {target}")
        library = re.match(r"#include <deal.II/(\w+)/", line)
        if library and layer in fe_free and library.group(1) != "base":
            problems.append(f"{path.relative_to(src)} includes deal.II/{library.group(1)}")
for problem in problems:
    print("FAIL:", problem)
print(f"checked {len(list(src.rglob('*.[ch]*')))} files: {len(problems)} problems")
sys.exit(1 if problems else 0)
