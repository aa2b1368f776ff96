"""Reading a scene's result folder for the figure scripts: its CSV tables and
the parameters it ran with."""
import csv
import pathlib
import re


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
