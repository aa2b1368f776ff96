"""Reading a scene's result folder for the figure scripts: its CSV tables and
the parameters it ran with."""
import csv
import os
import pathlib
import re
import subprocess


def read_table(folder, name):
    """The rows of folder/name as dictionaries, numbers as floats."""
    def value(text):
        try:
            return float(text)
        except ValueError:
            return text

    with open(pathlib.Path(folder) / name) as table:
        return [{key: value(text) for key, text in row.items()} for row in csv.DictReader(table)]


def parameter(folder, entry, default=None):
    """The value of `entry` in the folder's parameters.prm (the run's parameters)."""
    text = (pathlib.Path(folder) / "parameters.prm").read_text()
    match = re.search(r"^\s*set " + re.escape(entry) + r"\s*=\s*(.*?)\s*(#.*)?$", text, re.MULTILINE)
    return match.group(1) if match else default


def convention_note(folder):
    """What a statistical figure states about its normalisation."""
    if parameter(folder, "Convention", "paper") == "paper":
        return "paper convention: 3 pi R_p eta sqrt(V) = sqrt(2 pi), p0/sqrt(V) = zeta^theta"
    return "consistent convention: V, eta, R_p and p0 from the moments of the spectrum"


def corner_note(figure, folder):
    """Where a figure's numbers come from, in its lower left corner: the parameter file and commit of the run
    when the verification report draws it (PENNY_PARAMETERS, PENNY_COMMIT), else the results folder and the
    commit of these scripts."""
    parameters = os.environ.get("PENNY_PARAMETERS") or f"{pathlib.Path(folder).resolve()}/parameters.prm"
    commit = os.environ.get("PENNY_COMMIT")
    if not commit:
        scripts = pathlib.Path(__file__).resolve().parent
        commit = subprocess.run(["git", "-C", str(scripts), "rev-parse", "--short=10", "HEAD"],
                                capture_output=True, text=True).stdout.strip() or "unknown"
        commit = f"{commit} (the plotting scripts')"
    figure.text(0.005, 0.005, f"{parameters}; commit {commit}", fontsize=6, color="0.4")
