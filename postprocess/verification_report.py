#!/usr/bin/python3
"""The verification report: runs the verifying scenes and writes the evidence.

    /usr/bin/python3 postprocess/verification_report.py BUILD OUT [-np N] [--prms DIR] [--rerun]
                     [--documents FILE ...] [NAME ...]

Runs every parameter file of DIR (default prms/, the shipped full size) whose
scene has a verdict (a Verification subsection) and those that the blocks of
the --documents name (below), or the files NAME.prm named,
each under `mpirun -np N` when N > 1, in OUT/runs/NAME/ (relative output
folders land there). A NAME benchmark_X runs postprocess/benchmark_X.sh
BUILD OUT/runs/benchmark_X/results instead, with its own ranks and sizes:
its tables are for the documents, its verdict its exit status. It writes
OUT/report.md and OUT/report.html: the commit, the machine and its load, and per run the verdict (PASS, FAIL or
error) with the scene's own line on what it compared, its error and
tolerance, the wall time and peak memory, and its figures: those of
postprocess/plot_<scene>.py and, for the scenes with fields, the ParaView
pictures (pvpython under Xvfb), drawn after the run and embedded.

Resumable: a run whose record (OUT/runs/NAME/record.json) was made with the
same commit, parameter file and ranks is not run again unless --rerun. A
progress line before each run gives the time spent and an estimate of the
time left (from earlier records of the same run where there are any).

With --documents FILE ..., the report also rewrites the generated blocks of
those Markdown files (README.md and the pages of doc/ carry them), so that
the numbers in the documents are the report's. A block is the text between
a line `<!-- report: WHAT -->` and the next line `<!-- report: end -->`;
WHAT is
    claims             the table of the paper's claims, with the report's
                       commit, date and size and the verifying parameter
                       files it did not run;
    runs NAME ...      the verdict, comparison, error, tolerance, wall time,
                       peak memory and ranks of those runs, with the commit;
    file NAME PATH     the file PATH of run NAME's results folder (a table
                       the scene wrote): a .csv as a table, a .md as it is,
                       a .png (a figure) copied to figures/NAME-PATH beside
                       the document and shown, anything else verbatim in a
                       code block.
A block whose runs are not all in this report is kept as it is (each block
names the commit it came from) and listed on the screen. The files after
--documents run up to the next option: name the runs before it.

Each run and each figure script runs in a session of its own. SIGINT
(Ctrl-C), SIGTERM or SIGHUP stops the report: it stops the current run
(SIGTERM to its session, so penny removes its staging folder; SIGKILL 10 s
later), writes no record for it, says which records it kept, and exits
with 128 + the signal's number; the same command resumes. A report killed
by SIGKILL takes its run with it too (the run's first process gets SIGTERM
when the report dies), and the next report into the same folder first ends
whatever of a killed report's session is still running
(OUT/runs/NAME/session.json names it).

Exit status: 0 if every run passed and its figures were drawn, 1 if any
failed, stopped with an error or lost a figure, 2 for bad arguments, 128 + N
when stopped by signal N."""
import argparse
import contextlib
import csv
import ctypes
import fcntl
import hashlib
import html
import json
import os
import pathlib
import platform
import re
import signal
import subprocess
import sys
import time
import urllib.parse

REPOSITORY = pathlib.Path(__file__).resolve().parent.parent
# Where the benchmark scripts are that the report runs by name (benchmark_X.sh BUILD OUT).
BENCHMARKS = REPOSITORY / "postprocess"

# The paper's closed forms and assumptions, by the scene that checks them,
# with the section of doc/theory.md that derives the comparison. Scenes not
# listed verify the verifier (a solver against an exact answer).
PAPER_CLAIMS = {
    "penny-gap": ("K_I = 2 P sqrt(c/pi) [1 - (2/3) c^2/a^2] of the penny gap", "1"),
    "stress-intensity-curve": ("K_I(c) of the parabolic tension", "1"),
    "gap-size-adhesionless": ("adhesionless gap c/a = sqrt(3/2)", "1"),
    "adhesive-minimum": ("least peak tension p0 = psi (K_Ic^4/R_p)^(1/5), psi = 1.2021", "1"),
    "adhesive-equilibrium": ("the stable adhesive gap radius g(P)", "1"),
    "gap-tension-curve": ("p_hat(c_hat) = (c_hat^2 + 4/sqrt(c_hat))/5 (Fig. 2)", "1"),
    "fe-gap-area": ("the area-load curve from the closed-form g", "4"),
    "johnson-curves": ("Johnson's sinusoid as a periodic array of gaps (Fig. 1)", "6"),
    "jump-into-contact": ("Johnson's jump into contact", "6"),
    "periodic-gap": ("the periodic gap against Johnson's closed form", "6"),
    "westergaard-curve": ("Westergaard's adhesionless sinusoid", "6"),
    "elliptical-gap": ("elliptical gaps in 3D against Green-Sneddon", "8"),
    "elliptical-summits": ("the paper's remark on elliptical summits (Galin)", "8"),
    "bem-bisinusoid": ("gap closure 1 - p_bar/p* = psi (2 pi)^(2/5) alpha^(4/5) near full contact", "9"),
}


class Interrupted(Exception):
    """A signal that stops the report."""

    def __init__(self, number):
        super().__init__(signal.Signals(number).name)
        self.number = number


STOPPING_SIGNALS = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)


def stop_on_signals():
    """SIGINT, SIGTERM and SIGHUP raise Interrupted; the first one only (the stop then runs undisturbed)."""
    def interrupted(number, _):
        for each in STOPPING_SIGNALS:
            signal.signal(each, signal.SIG_IGN)
        raise Interrupted(number)
    for each in STOPPING_SIGNALS:
        if signal.getsignal(each) != signal.SIG_IGN:  # a signal the caller ignores (nohup) stays ignored
            signal.signal(each, interrupted)


def process_status(pid):
    """The fields of /proc/PID/stat after the command's name (state first), or None if there is no such process."""
    try:
        return pathlib.Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    except (OSError, IndexError):
        return None


def start_time(pid):
    """When process pid started (clock ticks after boot), None if there is none."""
    fields = process_status(pid)
    return int(fields[19]) if fields else None


def session_members(session):
    """The live processes of a session (Open MPI gives each rank a process group of its own, not a session)."""
    members = []
    for entry in os.listdir("/proc"):
        fields = process_status(entry) if entry.isdigit() else None
        if fields and fields[0] != "Z" and int(fields[3]) == session:
            members.append(int(entry))
    return members


def stop_session(session, grace=10):
    """Ends every process of a session: SIGTERM (penny removes its staging folder, mpirun passes it on to the
    ranks), SIGKILL to what is left after `grace` seconds; returns when none is left."""
    deadline, sent = time.time() + grace, set()
    while members := session_members(session):
        number = signal.SIGTERM if time.time() < deadline else signal.SIGKILL
        for pid in members:
            if (pid, number) not in sent:
                with contextlib.suppress(ProcessLookupError):
                    os.kill(pid, number)
                sent.add((pid, number))
        time.sleep(0.05)


def end_with_the_report(report=os.getpid(), prctl=ctypes.CDLL(None, use_errno=True).prctl):
    """In a child before its program starts: SIGTERM when the report dies, even by SIGKILL (PR_SET_PDEATHSIG)."""
    prctl(1, signal.SIGTERM)
    if os.getppid() != report:  # the report died before the request
        os._exit(1)
    signal.pthread_sigmask(signal.SIG_UNBLOCK, STOPPING_SIGNALS)


# The first process of a run's session: runs the command in its process group and, on SIGTERM (the report's
# death, by PR_SET_PDEATHSIG, or its stop), passes SIGTERM to the group (mpirun passes it on to its ranks,
# which have groups of their own; xvfb-run's X server is in the group), and 3 s later SIGKILL (pvpython
# outlives a SIGTERM).
SESSION_KEEPER = ('trap \'trap "" TERM; kill -TERM -- -$$; sleep 3; kill -KILL -- -$$\' TERM; '
                  '"$@" & wait $!; status=$?; wait; exit $status')


def in_session(command, folder, stdout, stderr, environment=None, timeout=None):
    """Runs a command in a session of its own, named in folder/session.json while it runs; its exit status
    (128 + N if a signal N ended it) and resource usage. An exception (an interruption, the timeout) stops the
    whole session before it goes on."""
    command = ["bash", "-c", SESSION_KEEPER, "session-keeper", *command]
    # Held back while the child starts: an interruption then finds it in the session marker's care.
    signal.pthread_sigmask(signal.SIG_BLOCK, STOPPING_SIGNALS)
    try:
        process = subprocess.Popen(command, cwd=folder, stdout=stdout, stderr=stderr, env=environment,
                                   start_new_session=True, preexec_fn=end_with_the_report)
    except BaseException:
        signal.pthread_sigmask(signal.SIG_UNBLOCK, STOPPING_SIGNALS)
        raise
    marker = folder / "session.json"
    try:
        signal.pthread_sigmask(signal.SIG_UNBLOCK, STOPPING_SIGNALS)
        write_whole(marker, json.dumps({"session": process.pid, "start": start_time(process.pid)}) + "\n")
        start = time.time()
        while True:
            pid, status, usage = os.wait4(process.pid, os.WNOHANG)
            if pid:
                break
            if timeout and time.time() - start > timeout:
                raise subprocess.TimeoutExpired(command, timeout)
            time.sleep(0.05)
    except BaseException:
        stop_session(process.pid)
        with contextlib.suppress(ChildProcessError):
            os.waitpid(process.pid, 0)
        marker.unlink(missing_ok=True)
        raise
    stop_session(process.pid)  # what the command left running behind it
    marker.unlink(missing_ok=True)
    return status, usage


def stop_left_sessions(out):
    """Ends the sessions a killed report left running (each named by runs/NAME/session.json)."""
    for marker in sorted(out.glob("runs/*/session.json")):
        with contextlib.suppress(OSError, ValueError, KeyError, TypeError):
            left = json.loads(marker.read_text())
            session = int(left["session"])
            leader = start_time(session)
            # A live process of that number that started at another time is not the session's.
            if leader is None or leader == left["start"]:
                if session_members(session):
                    print(f"{marker.parent.name}: stopping the run a killed report left behind", flush=True)
                stop_session(session)
        marker.unlink(missing_ok=True)


def refuse(message):
    sys.stderr.write(f"verification_report: error: {message}\n")
    sys.exit(2)


# The ParaView pictures of a scene's results (pvpython under Xvfb), beside
# the matplotlib figures postprocess/plot_<scene>.py draws.
PARAVIEW_PICTURES = {
    "penny-gap": "paraview_pictures.py",
    "elliptical-gap": "paraview_elliptical_front.py",
    "random-contact": "paraview_random_contact.py",
    "periodic-gap": "paraview_periodic_gap.py",
    "adhesive-random-contact": "paraview_adhesive_contact.py",
}


def figure_commands(scene, results):
    """The commands that draw the figures of a scene's results folder."""
    postprocess = REPOSITORY / "postprocess"
    commands = []
    plot = postprocess / f"plot_{scene.replace('-', '_')}.py"
    if scene == "convergence":
        commands.append(["/usr/bin/python3", str(postprocess / "plot_convergence.py"), str(results / "convergence"),
                         str(results)])
    elif plot.is_file():
        commands.append(["/usr/bin/python3", str(plot), str(results)])
    if scene in PARAVIEW_PICTURES and any(results.glob("*.vt?")):
        commands.append(["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24", "pvpython",
                         str(postprocess / PARAVIEW_PICTURES[scene]), str(results)])
    return commands


def read_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("build", type=pathlib.Path, help="the build folder holding penny")
    parser.add_argument("out", type=pathlib.Path, help="the report folder")
    parser.add_argument("names", nargs="*", help="parameter files to run, by name (default: every verifying one)")
    parser.add_argument("-np", dest="ranks", type=int, default=1, help="MPI ranks of each run (default 1)")
    parser.add_argument("--prms", type=pathlib.Path, default=REPOSITORY / "prms", help="where the parameter files are")
    parser.add_argument("--rerun", action="store_true", help="run again what already has a record")
    parser.add_argument("--documents", type=pathlib.Path, nargs="+", default=[],
                        help="Markdown files whose generated blocks the report rewrites")
    arguments = parser.parse_intermixed_args()
    arguments.penny = (arguments.build / "penny").resolve()
    # The runs and their figures work in folders of their own: relative paths would be taken from there.
    arguments.out = arguments.out.resolve()
    if not os.access(arguments.penny, os.X_OK):
        parser.error(f"no penny program in {arguments.build}")
    if not 1 <= arguments.ranks <= 1024:
        parser.error(f"-np = {arguments.ranks} is outside the allowed range [1, 1024]")
    if not arguments.prms.is_dir():
        parser.error(f"--prms {arguments.prms} is not a folder")
    if arguments.out.exists() and not arguments.out.is_dir():
        parser.error(f"the report folder {arguments.out} exists and is not a folder")
    for document in arguments.documents:
        try:
            generated_blocks(document.read_text())
        except (OSError, ValueError) as error:  # UnicodeDecodeError is a ValueError
            parser.error(f"--documents {document}: {error}")
    return arguments


BLOCK_START = re.compile(r"^<!-- report: (.*?) -->\n", re.MULTILINE)
BLOCK_END = "<!-- report: end -->"


def runs_named(what):
    """The runs a block's WHAT names."""
    return what[1:] if what[0] == "runs" else what[1:2]


def generated_blocks(text):
    """The generated blocks of a Markdown text: (WHAT as words, start, stop) with text[start:stop] the block's
    body; ValueError for a block that is not closed or does not say what it holds."""
    blocks, position = [], 0
    while (start := BLOCK_START.search(text, position)):
        what = start.group(1).split()
        if what == ["end"]:
            raise ValueError(f"'{BLOCK_END}' without its start (line {text.count(chr(10), 0, start.start()) + 1})")
        stop = text.find("\n" + BLOCK_END, start.end() - 1)
        if stop < 0:
            raise ValueError(f"the block '{start.group(0).strip()}' has no line '{BLOCK_END}'")
        valid = (what == ["claims"] or (len(what) >= 2 and what[0] == "runs")
                 or (len(what) == 3 and what[0] == "file"))
        if not valid:
            raise ValueError(f"'{start.group(0).strip()}': WHAT is 'claims', 'runs NAME ...' or 'file NAME PATH'")
        if any("/" in name for name in runs_named(what)) or (
                what[0] == "file" and (what[2].startswith("/") or ".." in what[2].split("/"))):
            raise ValueError(f"'{start.group(0).strip()}': NAME is a run's name, PATH a file in its results folder")
        blocks.append((what, start.end(), stop + 1))
        position = stop + 1 + len(BLOCK_END)
    return blocks


def text_of(path):
    """A file's text; bytes that are not UTF-8 (a Latin-1 comment, which penny accepts) shown as U+FFFD."""
    return path.read_bytes().decode("utf-8", errors="replace")


def scene_of(prm):
    if prm.suffix == ".sh":
        return "benchmark"
    match = re.search(r"^\s*set\s+Scene\s*=\s*(\S+)", text_of(prm), re.MULTILINE)
    return match.group(1) if match else "penny-gap"


def has_verdict(penny, scene, cache={}):
    if scene not in cache:
        entries = subprocess.run([str(penny), "--print-parameters", scene], capture_output=True, text=True)
        cache[scene] = entries.returncode == 0 and "\nsubsection Verification" in "\n" + entries.stdout
    return cache[scene]


def selected_files(arguments):
    """The named parameter files, or every verifying one and those the documents' blocks name."""
    names = arguments.names or [f.stem for f in verifying_files(arguments)] + sorted(
        {name for document in arguments.documents for what, _, _ in generated_blocks(document.read_text())
         for name in runs_named(what)})
    files = [BENCHMARKS / f"{name}.sh" if name.startswith("benchmark_") else
             arguments.prms / (name if name.endswith(".prm") else name + ".prm") for name in dict.fromkeys(names)]
    missing = [str(f) for f in files if not f.is_file()]
    if missing:
        refuse(f"no parameter file or benchmark script {', '.join(missing)}")
    return files


def verifying_files(arguments):
    return [f for f in sorted(arguments.prms.glob("*.prm")) if has_verdict(arguments.penny, scene_of(f))]


def sources(build):
    """The source folder the build was made from (its CMakeCache.txt names it), or None."""
    cache = build / "CMakeCache.txt"
    found = re.search(r"^CMAKE_HOME_DIRECTORY:INTERNAL=(.*)$", cache.read_text(), re.MULTILINE) if cache.is_file() else None
    return pathlib.Path(found.group(1)) if found else None


def commit(build):
    """The commit of the sources the build was made from, with a hash of their uncommitted changes where
    there are any."""
    folder = sources(build)
    if not folder:
        return "unknown (no CMakeCache.txt in the build folder)"

    def git(*words):
        return subprocess.run(["git", "-C", str(folder), *words], capture_output=True, text=True).stdout
    head = git("rev-parse", "--short=10", "HEAD").strip() or "unknown"
    changes = git("diff", "HEAD")
    return head + ("+" + hashlib.sha256(changes.encode()).hexdigest()[:8] if changes else "")


def machine():
    model = next((line.split(":", 1)[1].strip() for line in open("/proc/cpuinfo") if line.startswith("model name")), "?")
    memory = next((int(line.split()[1]) for line in open("/proc/meminfo") if line.startswith("MemTotal")), 0)
    return f"{platform.node()}: {os.cpu_count()} x {model}, {memory / 2**20:.1f} GiB"


def load_average():
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def run(arguments, prm, key, folder):
    """Runs one parameter file or benchmark script in its folder; its record."""
    folder.mkdir(parents=True, exist_ok=True)
    if prm.suffix == ".sh":
        command = [str(prm), str(arguments.build.resolve()), str((folder / "results").resolve())]
    else:
        command = [str(arguments.penny), str(prm.resolve())]
        if arguments.ranks > 1:
            command = ["mpirun", "-np", str(arguments.ranks)] + command
    environment = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    load_before, start = load_average(), time.time()
    with open(folder / "stdout.txt", "w") as stdout, open(folder / "stderr.txt", "w") as stderr:
        status, usage = in_session(command, folder, stdout, stderr, environment)
    wall = time.time() - start
    output = text_of(folder / "stdout.txt")
    errors = text_of(folder / "stderr.txt")
    code = os.waitstatus_to_exitcode(status)
    passed = re.search(r"^PASS: (.*)$", output, re.MULTILINE)
    failed = re.search(r"^penny: FAIL: (.*)$", errors, re.MULTILINE)
    if code == 0:
        verdict, message = "PASS", passed.group(1) if passed else "ran to its results (no verdict)"
    elif failed:
        verdict, message = "FAIL", failed.group(1)
    else:
        last = [line for line in errors.splitlines() if line.strip()]
        verdict, message = "ERROR", (last[-1] if last else f"exit status {code}")
    # penny's last line names the folder: "Results in FOLDER/: FILE ..." (FOLDER may hold blanks).
    results = re.search(r"^Results in (.+)/: ", output, re.MULTILINE)
    results = "results" if prm.suffix == ".sh" else results.group(1) if results else None
    # The figures, from a run that finished; a script that fails, or a folder not found, is reported.
    figure_errors = []
    if code == 0 and not (results and (folder / results).is_dir()):
        figure_errors.append("no results folder named on the screen: figures not drawn")
    elif code == 0:
        # The figures name the run's parameter file and commit in a corner (postprocess/results.py).
        stamp = dict(os.environ, PENNY_PARAMETERS=str(prm.resolve()), PENNY_COMMIT=key["commit"])
        with open(folder / "figures.txt", "w") as log:
            for command in figure_commands(scene_of(prm), folder / results):
                # Xvfb now and then gives pvpython no window (tests/check_paraview.sh): three tries.
                for _ in range(3 if command[0] == "xvfb-run" else 1):
                    status, _ = in_session(command, folder, log, subprocess.STDOUT, stamp, timeout=1800)
                    if status == 0:
                        break
                if status != 0:
                    script = next(word for word in command if word.endswith(".py"))
                    figure_errors.append(f"{pathlib.Path(script).name} exit {os.waitstatus_to_exitcode(status)}")
    return {"key": key, "scene": scene_of(prm), "verdict": verdict, "message": message, "exit": code,
            "wall time (s)": round(wall, 2), "peak memory (MB)": round(usage.ru_maxrss / 1024),
            "ranks": "its own" if prm.suffix == ".sh" else arguments.ranks, "load average before": load_before,
            "load average after": load_average(), "results": results, "figure errors": figure_errors,
            "date": time.strftime("%Y-%m-%d %H:%M:%S")}


def write_whole(path, text):
    """A file that is there complete or not at all (written beside, then renamed)."""
    write_whole_bytes(path, text.encode())


def write_whole_bytes(path, data):
    partial = path.with_name(path.name + ".partial")
    partial.write_bytes(data)
    os.replace(partial, path)


def figures(folder, record):
    if not record["results"]:
        return []
    return sorted(str(p.relative_to(folder.parent.parent)) for p in (folder / record["results"]).glob("*.png"))


def numbers_in(message):
    """The error and tolerance of a verdict line 'WHAT ERROR <= ENTRY = TOLERANCE'."""
    match = re.search(r"([-+0-9.eE]+) (<=|>) [^=]*= ?([-+0-9.eE]+)\s*$", message)
    return (match.group(1), match.group(3)) if match else ("", "")


def short_number(cell):
    """A table cell with a real number written to 10 significant digits (the scenes write 17)."""
    if re.fullmatch(r"[-+]?(\d+\.\d*|\.\d+|\d+(\.\d*)?[eE][-+]?\d+)", cell.strip()):
        return f"{float(cell):.10g}"
    return cell


def markdown_table(columns, table):
    lines = ["| " + " | ".join(columns) + " |", "|" + "---|" * len(columns)]
    return "\n".join(lines + ["| " + " | ".join(c.replace("|", "\\|") for c in row) + " |" for row in table])


def write_report(arguments, records, header):
    rows, claims = [], []
    for name, folder, record in records:
        error, tolerance = numbers_in(record["message"])
        message = record["message"] + "".join(f" (figure failed: {e})" for e in record["figure errors"])
        rows.append([name, record["scene"], record["verdict"], message, error, tolerance,
                     f"{record['wall time (s)']:.1f}", str(record["peak memory (MB)"]), str(record["ranks"]),
                     record["load average before"], record["date"]])
        if record["scene"] in PAPER_CLAIMS:
            claim, section = PAPER_CLAIMS[record["scene"]]
            claims.append((list(PAPER_CLAIMS).index(record["scene"]),
                           [claim, f"doc/theory.md section {section}", name, record["verdict"], error, tolerance]))
    # In the paper's order (PAPER_CLAIMS), whatever order the runs were named in.
    claims = [row for _, row in sorted(claims, key=lambda claim: claim[0])]
    claim_columns = ["the paper's claim", "derived in", "run", "verdict", "error", "tolerance"]
    run_columns = ["run", "scene", "verdict", "what was compared", "error", "tolerance", "wall time (s)",
                   "peak memory (MB)", "ranks", "load average at start", "finished"]

    def html_table(columns, table):
        head = "".join(f"<th>{html.escape(c)}</th>" for c in columns)
        body = "".join("<tr>" + "".join(f'<td class="{html.escape(c)}">{html.escape(c)}</td>' for c in row) + "</tr>"
                       for row in table)
        return f"<table><tr>{head}</tr>{body}</table>"

    passed = sum(r[2] == "PASS" and not record["figure errors"] for r, (_, _, record) in zip(rows, records))
    summary = f"{passed} of {len(rows)} runs passed (a run passes with its verdict and its figures)."
    pictures = [(name, f) for name, folder, record in records for f in figures(folder, record)]
    markdown = ["# penny-verifier: verification report", "", *[f"- {k}: {v}" for k, v in header.items()], "",
                summary, "", "## The paper's claims", "", markdown_table(claim_columns, claims), "",
                "## Every run", "", markdown_table(run_columns, rows), "",
                "Each run's screen output, tables and fields are in runs/NAME/.", ""]
    markdown += ["## Figures", ""] + [f"![{name}]({urllib.parse.quote(f)})" for name, f in pictures] if pictures else []
    write_whole(arguments.out / "report.md", "\n".join(markdown) + "\n")
    page = ["<!DOCTYPE html><html><head><meta charset='utf-8'><title>penny-verifier: verification report</title>",
            "<style>body{font-family:sans-serif} table{border-collapse:collapse} td,th{border:1px solid #999;"
            "padding:2px 6px} td.PASS{background:#cfc} td.FAIL,td.ERROR{background:#fcc}</style></head><body>",
            "<h1>penny-verifier: verification report</h1><ul>",
            *[f"<li>{html.escape(k)}: {html.escape(str(v))}</li>" for k, v in header.items()],
            f"</ul><p>{summary}</p><h2>The paper's claims</h2>", html_table(claim_columns, claims),
            "<h2>Every run</h2>", html_table(run_columns, rows)]
    page += ["<h2>Figures</h2>"] + [f"<p>{html.escape(n)}<br><img src='{html.escape(urllib.parse.quote(f))}'></p>"
                                    for n, f in pictures]
    write_whole(arguments.out / "report.html", "\n".join(page) + "</body></html>\n")
    if arguments.documents:
        write_documents(arguments, header, summary, markdown_table(claim_columns, claims), records)
    return passed == len(rows)


def write_documents(arguments, header, summary, claims_table, records):
    """Rewrites the generated blocks of the documents from this report's records."""
    # Where the parameter files are, relative to the build's sources where they lie in them.
    prms, folder = arguments.prms.resolve(), sources(arguments.build)
    where = prms.relative_to(folder.resolve()) if folder and prms.is_relative_to(folder.resolve()) else prms
    by_name = {name: (folder, record) for name, folder, record in records}
    source = f"commit {header['commit']}, {arguments.ranks} rank(s) per run"

    def claims():
        block = [f"From the verification report of commit {header['commit']} (started {header['started']}; "
                 f"{header['machine']}; parameter files in {where}/, {arguments.ranks} rank(s) each): {summary}", "",
                 claims_table, ""]
        others = sorted(f.stem for f in verifying_files(arguments) if f.stem not in by_name)
        if others:
            block += [f"Verifying parameter files that report did not run: {', '.join(others)}.", ""]
        return block

    def runs(names):
        columns = ["run", "verdict", "what was compared", "error", "tolerance", "wall time (s)",
                   "peak memory (MB)", "ranks"]
        table = []
        for name in names:
            record = by_name[name][1]
            error, tolerance = numbers_in(record["message"])
            table.append([name, record["verdict"], record["message"], error, tolerance,
                          f"{record['wall time (s)']:.1f}", str(record["peak memory (MB)"]), str(record["ranks"])])
        return [f"From the verification report ({source}, {header['started']}):", "",
                markdown_table(columns, table), ""]

    def file(name, path, document):
        folder, record = by_name[name]
        table = folder / (record["results"] or ".") / path
        if not table.is_file():
            return None
        if table.suffix == ".png":
            # A figure: copied beside the document (figures/NAME-FILE), shown where the block stands.
            copy = pathlib.Path("figures") / f"{name}-{path}"
            (document.parent / "figures").mkdir(exist_ok=True)
            write_whole_bytes(document.parent / copy, table.read_bytes())
            return [f"`{path}` of run {name}, from the verification report ({source}, {header['started']}):", "",
                    f"![{path} of run {name}]({urllib.parse.quote(str(copy))})", ""]
        text = text_of(table).rstrip("\n")
        rows = list(csv.reader(text.splitlines()))
        if table.suffix == ".csv" and rows:
            body = [markdown_table(rows[0], [[short_number(cell) for cell in row] for row in rows[1:]])]
        else:
            body = [text] if table.suffix == ".md" else ["```", text, "```"]
        return [f"`{path}` of run {name}, from the verification report ({source}, {header['started']}):", "",
                *body, ""]

    for document in arguments.documents:
        text = document.read_text()
        pieces, position = [], 0
        for what, start, stop in generated_blocks(text):
            missing = [n for n in runs_named(what) if n not in by_name]
            lines = None if missing else claims() if what[0] == "claims" else runs(what[1:]) if what[0] == "runs" \
                else file(*what[1:], document)
            if lines is None:
                reason = f"not in this report: {', '.join(missing)}" if missing else "the run wrote no such file"
                print(f"{document}: kept the block '{' '.join(what)}' ({reason})")
                continue
            pieces += [text[position:start], "\n".join(lines) + "\n"]
            position = stop
        write_whole(document, "".join(pieces) + text[position:])


def main():
    stop_on_signals()
    arguments = read_arguments()
    files = selected_files(arguments)
    if not files:
        refuse(f"no verifying parameter file in {arguments.prms}")
    # One report at a time in a folder (the kernel drops the lock when a run dies).
    arguments.out.mkdir(parents=True, exist_ok=True)
    lock = open(arguments.out / ".report.lock", "w")
    try:
        fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        refuse(f"another report is running in {arguments.out}")
    stop_left_sessions(arguments.out)
    revision = commit(arguments.build)
    header = {"commit": revision, "machine": machine(), "load average at start": load_average(),
              "parameter files": str(arguments.prms), "ranks per run": arguments.ranks,
              "started": time.strftime("%Y-%m-%d %H:%M:%S")}
    records = []
    try:
        run_all(arguments, files, revision, records)
    except Interrupted as interruption:
        finished = [name for name, _, _ in records]
        kept = f"kept the records of {', '.join(finished)}" if finished else "no run of this call finished"
        sys.stderr.write(f"verification_report: stopped by {interruption} (its run stopped, not recorded); {kept} "
                         f"in {arguments.out / 'runs'}; the same command resumes\n")
        return 128 + interruption.number
    header["load average at end"] = load_average()
    all_passed = write_report(arguments, records, header)
    print(f"Report: {arguments.out / 'report.md'} and report.html")
    return 0 if all_passed else 1


def run_all(arguments, files, revision, records):
    """Runs the files, or takes their records; appends (name, folder, record) to `records` as each finishes."""
    spent, ran = 0.0, 0
    for index, prm in enumerate(files):
        name, folder = prm.stem, arguments.out / "runs" / prm.stem
        key = {"commit": revision, "parameters": hashlib.sha256(prm.read_bytes()).hexdigest(),
               "ranks": arguments.ranks}
        previous = json.loads((folder / "record.json").read_text()) if (folder / "record.json").is_file() else None
        if previous and previous["key"] == key and not arguments.rerun:
            print(f"[{index + 1}/{len(files)}] {name}: {previous['verdict']} (recorded {previous['date']})", flush=True)
            records.append((name, folder, previous))
            continue
        # Time left: each remaining run as long as its last record, or as the mean so far.
        expected = []
        for later in files[index:]:
            record = arguments.out / "runs" / later.stem / "record.json"
            expected.append(json.loads(record.read_text())["wall time (s)"] if record.is_file() else None)
        known = [t for t in expected if t is not None]
        mean = spent / ran if ran else sum(known) / len(known) if known else None
        left = (f"about {sum(t if t is not None else mean for t in expected):.0f} s left" if mean is not None
                else "the time left is known once a run has finished")
        print(f"[{index + 1}/{len(files)}] {name}: running ({spent:.0f} s so far, {left})", flush=True)
        if folder.exists():
            for stale in ("record.json", "stdout.txt", "stderr.txt", "figures.txt"):
                (folder / stale).unlink(missing_ok=True)
        record = run(arguments, prm, key, folder)
        spent, ran = spent + record["wall time (s)"], ran + 1
        # A run that found its folder held did not run: it gets no record (the next call runs it).
        if "is in use by another penny run" not in record["message"]:
            write_whole(folder / "record.json", json.dumps(record, indent=1) + "\n")
        print(f"    {record['verdict']}: {record['message']} ({record['wall time (s)']:.1f} s)"
              + "".join(f"; figure failed: {e}" for e in record["figure errors"]), flush=True)
        records.append((name, folder, record))


if __name__ == "__main__":
    try:
        sys.exit(main())
    except (OSError, subprocess.SubprocessError) as error:
        sys.stderr.write(f"verification_report: error: {error}\n")
        sys.exit(1)
    except Interrupted as interruption:
        sys.stderr.write(f"verification_report: stopped by {interruption} before any run\n")
        sys.exit(128 + interruption.number)
