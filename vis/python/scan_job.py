"""One scan of a batch: fit, strokes, stats and transfer, each step a run of
the `meshpaint` executable in its own process.

A step's process owns its OpenCL context and nothing else does, so no
context is shared between processes or threads, a crash ends only that
step, and a hang is ended by the scan's time limit. The Dask worker that
calls process_scan only starts processes and moves files.

Outputs are built in a hidden folder beside the scan's folder and swapped
in whole when every step succeeded; a failed scan leaves the previous
results as they were. The log of every run goes to logs/NAME.log.
"""
import json
import os
import shutil
import signal
import subprocess
import time
import uuid

#: The scan's folder once it succeeded: what each step writes there.
PROJECT = "project.meshpaint"
TRANSFERRED = "scan.vtp"
STATS = "stats.csv"
FIT_REPORT = "fit.json"
LOGS = "logs"

#: Rows of the summary, in CSV column order.
COLUMNS = ("scan", "status", "triangles", "fit_rms_percent", "fit_worst_percent", "seconds", "error", "path")


class StepFailed(Exception):
    """A step that did not succeed; the message is the one line for the summary."""


def find_executable(executable=None):
    """The meshpaint program: the one given, else the build's (beside this package), else PATH."""
    if executable:
        return executable
    here = os.path.dirname(os.path.abspath(__file__))
    beside = os.path.join(here, os.pardir, os.pardir, "bin", "meshpaint")
    if os.access(beside, os.X_OK):
        return os.path.normpath(beside)
    found = shutil.which("meshpaint")
    if found:
        return found
    raise StepFailed("cannot find the meshpaint program (not beside the package, not on PATH)")


def fit_errors(path):
    """(RMS, worst) in % of the diagonal from fit's JSON report (`fit --report`): the larger of the two directions."""
    try:
        with open(path, encoding="utf-8") as f:
            report = json.load(f)
        errors = [report[key] for key in ("scan_to_fit", "fit_to_scan")]
        return (max(float(e["rms_percent"]) for e in errors), max(float(e["max_percent"]) for e in errors))
    except (OSError, ValueError, KeyError, TypeError) as e:
        raise StepFailed(f"meshpaint fit: its report {os.path.basename(path)} is unreadable ({e})") from None


def count_triangles(path):
    """Triangles of a VTK XML PolyData file, polygons and strips fanned."""
    import vtkmodules.vtkIOXML as io  # a worker imports VTK only when it counts

    reader = io.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    poly = reader.GetOutput()
    total = 0
    for cells in (poly.GetPolys(), poly.GetStrips()):
        total += cells.GetNumberOfConnectivityIds() - 2 * cells.GetNumberOfCells()
    return total


def error_line(command, result):
    """The one line that says why a step failed."""
    lines = [l.strip() for l in result.stderr.splitlines() if l.strip()]
    prefix = f"meshpaint {command}:"
    said = [l for l in lines if l.startswith(prefix) and not l.startswith(prefix + " warning:")]
    if result.returncode < 0:
        try:
            name = signal.Signals(-result.returncode).name
        except ValueError:
            name = str(-result.returncode)
        return f"{prefix} killed by signal {name}" + (f" ({said[0]})" if said else "")
    if said:
        return said[0]  # the message; a kernel build failure adds its log on later lines
    if lines:
        return f"{prefix} {lines[-1]}"
    return f"{prefix} exit code {result.returncode}"


class _Steps:
    """Runs the steps of one scan within its time limit and keeps their log."""

    def __init__(self, executable, deadline, limit):
        self.executable = executable
        self.deadline = deadline
        self.limit = limit
        self.log = []

    def run(self, command, *args):
        argv = [self.executable, command, *args]
        left = None if self.deadline is None else self.deadline - time.monotonic()
        self.log.append("$ " + " ".join(argv))
        if left is not None and left <= 0:
            raise StepFailed(f"meshpaint {command}: not started, the scan's time limit of {self.limit:g} s is spent")
        try:
            result = subprocess.run(argv, capture_output=True, text=True, timeout=left, stdin=subprocess.DEVNULL)
        except subprocess.TimeoutExpired as e:
            self.log.append(_text(e.stdout) + _text(e.stderr) + "(killed: time limit)")
            raise StepFailed(f"meshpaint {command}: timed out (the scan's time limit is {self.limit:g} s)") from None
        except OSError as e:
            raise StepFailed(f"cannot run {self.executable}: {e.strerror}") from None
        self.log.append(result.stdout + result.stderr + f"(exit {result.returncode})")
        if result.returncode != 0:
            raise StepFailed(error_line(command, result))
        return result.stdout


def _text(data):
    if data is None:
        return ""
    return data.decode(errors="replace") if isinstance(data, bytes) else data


def write_atomically(path, text):
    """Writes a text file through a temporary beside it, renamed over the target."""
    folder, name = os.path.split(path)
    temporary = os.path.join(folder, f".{name}.tmp-{os.getpid()}-{uuid.uuid4().hex[:8]}")
    try:
        with open(temporary, "w", newline="") as f:
            f.write(text)
        os.replace(temporary, path)
    except BaseException:
        if os.path.exists(temporary):
            os.unlink(temporary)
        raise


def _swap_in(built, target):
    """Puts the folder `built` in the place of `target` (which may exist)."""
    if not os.path.isdir(target):
        os.rename(built, target)
        return
    old = os.path.join(os.path.dirname(target), f".{os.path.basename(target)}.old-{uuid.uuid4().hex[:8]}")
    os.rename(target, old)
    os.rename(built, target)
    shutil.rmtree(old, ignore_errors=True)


def process_scan(scan, name, output, strokes, fit=False, labels=None, level=None, timeout=None, executable=None):
    """Runs the batch's steps on one scan; returns its summary row (a dict of COLUMNS).

    scan, output, strokes and labels are absolute paths as the worker sees
    them. Never raises for a failing scan: the row says what failed.
    """
    start = time.monotonic()
    row = dict.fromkeys(COLUMNS)
    row.update(scan=name, path=scan, status="failed", error="")
    built = os.path.join(output, f".{name}.tmp-{os.getpid()}-{uuid.uuid4().hex[:8]}")
    steps = None
    try:
        steps = _Steps(find_executable(executable), None if not timeout else start + timeout, timeout)
        os.makedirs(built)
        project = os.path.join(built, PROJECT)
        level_args = [] if level is None else ["--level", str(level)]
        if fit:
            report = os.path.join(built, FIT_REPORT)
            steps.run("fit", scan, *level_args, "--quiet", "--report", report, "-o", project)
            row["fit_rms_percent"], row["fit_worst_percent"] = fit_errors(report)
            source, level_args = project, []  # the project carries its level
        else:
            source = scan
        label_args = [] if labels is None else ["--labels", labels]
        steps.run("paint", source, "--strokes", strokes, *level_args, *label_args, "--quiet", "-o", built,
                  "--save", project)
        write_atomically(os.path.join(built, STATS), steps.run("stats", project, "--csv"))
        transferred = os.path.join(built, TRANSFERRED)
        steps.run("transfer", project, "--to", scan, "--geometry", "--quiet", "-o", transferred)
        row["triangles"] = count_triangles(transferred)
        _swap_in(built, os.path.join(output, name))
        row["status"] = "ok"
    except StepFailed as e:
        row["error"] = str(e)
    except OSError as e:
        row["error"] = f"meshpaint.batch: {e.filename}: {e.strerror}" if e.filename else f"meshpaint.batch: {e}"
    finally:
        shutil.rmtree(built, ignore_errors=True)
        row["seconds"] = round(time.monotonic() - start, 3)
        _write_log(output, name, row, steps)
    return row


def _write_log(output, name, row, steps):
    """logs/NAME.log: the steps run, their output, and the outcome."""
    try:
        folder = os.path.join(output, LOGS)
        os.makedirs(folder, exist_ok=True)
        lines = [] if steps is None else list(steps.log)
        lines.append(f"{row['status']} in {row['seconds']:g} s" + (f": {row['error']}" if row["error"] else ""))
        write_atomically(os.path.join(folder, name + ".log"), "\n".join(lines) + "\n")
    except OSError:
        pass  # the log is a convenience; the summary row still says what happened
