"""Checks the layers of src/ (doc/architecture.md): each folder includes only
the folders listed for it below, with no exception for single files; the layers
without finite elements include no deal.II header beyond deal.II/base; and
no layer below problems/ names an entry of the parameter file (a subsection
of one, "Mesh/...", inside a string), since errors that name an entry are
raised where it is read.  Usage: check_layering.py SRC"""
import pathlib
import re
import sys

src = pathlib.Path(sys.argv[1])
# What each layer may include besides itself, from the bottom up.
below_fe = ["numerics", "input", "parallel", "closed_forms"]
fe_layers = below_fe + ["fe", "fracture", "searches"]
spectral = ["fourier", "contact", "statistics"]
allowed = {
    "numerics": [],
    "input": [],
    "parallel": ["numerics", "input"],
    "closed_forms": ["numerics", "input"],
    "fe": below_fe,
    "fracture": below_fe + ["fe"],
    "searches": below_fe + ["fe", "fracture"],
    "fourier": [],
    "contact": ["numerics", "input", "parallel", "closed_forms", "fourier"],
    "statistics": below_fe + ["fourier", "contact"],
    "topography": ["numerics", "input", "fourier", "statistics"],
    "output": fe_layers,
    "problems": fe_layers + spectral + ["topography", "output"],
    "scenes": fe_layers + spectral + ["topography", "output", "problems"],
    "apps": ["input", "parallel", "scenes"],
}
fe_free = set(below_fe + spectral + ["topography"])  # no deal.II beyond deal.II/base
reads_entries = {"problems", "scenes", "apps"}

files = sorted(path for path in src.rglob("*.[ch]*") if path.is_file())
subsections = set()
for path in files:
    if path.relative_to(src).parts[0] in reads_entries:
        subsections |= set(re.findall(r'subsection\("([^"]+)"', path.read_text()))

problems = []
for path in files:
    layer = path.relative_to(src).parts[0]
    if layer not in allowed:
        problems.append(f"{path.relative_to(src)} is in no known layer")
        continue
    text = path.read_text()
    for line in text.splitlines():
        own = re.match(r'#include "([^"]+)"', line)
        if own:
            target = own.group(1)
            if not any(target.startswith(folder + "/") for folder in [layer] + allowed[layer]):
                problems.append(f"{path.relative_to(src)} includes {target}")
        library = re.match(r"#include <deal.II/(\w+)/", line)
        if library and layer in fe_free and library.group(1) != "base":
            problems.append(f"{path.relative_to(src)} includes deal.II/{library.group(1)}")
    if layer not in reads_entries:
        for literal in re.findall(r'"((?:[^"\\]|\\.)*)"', text):
            for name in subsections:
                if name + "/" in literal:
                    problems.append(f"{path.relative_to(src)} names the entry '{literal}'")
for problem in problems:
    print("FAIL:", problem)
print(f"checked {len(files)} files against {len(subsections)} subsections: {len(problems)} problems")
sys.exit(1 if problems else 0)
