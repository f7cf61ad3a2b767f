"""Command-line conventions: --help, --version, and the one-line error contract
for what the libraries print, low memory and hostile values.

Run by CTest with MESHPAINT_BIN (the executable) and MESHPAINT_SOURCE_DIR set.
"""
import glob
import json
import os
import re
import subprocess

import pytest

BIN = os.environ["MESHPAINT_BIN"]
BENCH = os.path.join(os.path.dirname(BIN), "meshpaint-bench")
SOURCE = os.environ["MESHPAINT_SOURCE_DIR"]
SCANS = os.path.join(SOURCE, "data", "scans")
STROKES = os.path.join(SOURCE, "data", "strokes", "bunny_demo.json")
CUBE = os.path.join(SOURCE, "tests", "support", "cube.obj")
COMMANDS = ["demo", "info", "subdivide", "paint", "view", "stats", "fit", "transfer", "devices", "bench"]


def run(*args, env=None, preexec_fn=None, program=BIN):
    full = dict(os.environ, **(env or {}))
    return subprocess.run([program, *args], capture_output=True, text=True, timeout=600, env=full,
                          preexec_fn=preexec_fn)


def one_line(r):
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1, r.stderr[:3000]
    assert lines[0].startswith("meshpaint "), lines[0]
    return lines[0]


def project_version():
    with open(os.path.join(SOURCE, "CMakeLists.txt")) as f:
        return re.search(r"project\(meshpaint VERSION ([0-9.]+)", f.read()).group(1)


@pytest.mark.parametrize("flag", ["--help", "-h"])
@pytest.mark.parametrize("command", COMMANDS)
def test_command_help_prints_its_usage_and_exits_0(command, flag):
    r = run(command, flag)
    assert r.returncode == 0, r.stderr
    assert r.stderr == ""
    assert r.stdout.startswith("usage: meshpaint " + command), r.stdout
    assert "docs/cli.md" in r.stdout


def test_help_after_other_arguments_and_help_command():
    r = run("paint", "cube.obj", "--strokes", "s.json", "--help")
    assert r.returncode == 0 and r.stdout.startswith("usage: meshpaint paint"), r.stderr
    assert run("help", "fit").stdout == run("fit", "--help").stdout
    for args in (["--help"], ["-h"], ["help"]):
        r = run(*args)
        assert r.returncode == 0 and r.stdout.startswith("usage: meshpaint COMMAND"), r.stderr
        assert "--version" in r.stdout


@pytest.mark.parametrize("flag", ["--help", "-h"])
def test_help_command_help_prints_its_usage(flag):
    r = run("help", flag)
    assert r.returncode == 0, r.stderr
    assert r.stdout.startswith("usage: meshpaint help [COMMAND]"), r.stdout


def test_version_with_an_argument_is_an_error():
    r = run("--version", "extra")
    assert r.returncode == 2 and r.stdout == ""
    assert "'extra'" in one_line(r)


def parsed_options():
    """Each command's options as app/ parses them: Args args("NAME", argv, {flags}, {options})."""
    found = {}
    for path in glob.glob(os.path.join(SOURCE, "app", "*_command.cpp")):
        with open(path) as f:
            text = f.read()
        for m in re.finditer(r'Args args\("(\w+)", argv, \{([^}]*)\},\s*\{([^}]*)\}', text):
            found[m.group(1)] = re.findall(r'"(-[-\w]+)"', m.group(2) + m.group(3))
    return found


def test_each_command_usage_lists_every_option_it_takes():
    options = parsed_options()
    assert {"paint", "fit", "transfer", "info"} <= set(options), options
    for command, taken in options.items():
        usage = run(command, "--help").stdout
        entry, footer = usage.split("\n\n", 1)
        # A footer entry starts in the first column and names its commands before its first colon.
        notes = [e for e in re.split(r"\n(?=\S)", footer) if re.search(rf"\b{command}\b", e.split(":")[0])]
        for option in taken:
            assert re.search(rf"{option}\b", entry + "\n".join(notes)), (command, option, usage)
    assert "model.gltf" in run("paint", "--help").stdout


def test_help_of_an_unknown_command_is_an_error():
    r = run("nope", "--help")
    assert r.returncode == 2
    assert "unknown command 'nope'" in one_line(r)


def test_version_comes_from_the_project_version():
    r = run("--version")
    assert r.returncode == 0, r.stderr
    assert r.stdout == "meshpaint " + project_version() + "\n"
    r = run("--version", program=BENCH)
    assert r.returncode == 0, r.stderr
    assert r.stdout == "meshpaint-bench " + project_version() + "\n"


@pytest.mark.parametrize("flag", ["--help", "-h"])
def test_bench_program_help(flag):
    for args in ([flag], ["paint", flag]):
        r = run(*args, program=BENCH)
        assert r.returncode == 0 and r.stdout.startswith("usage: meshpaint bench"), r.stderr


def test_vtk_messages_do_not_reach_stderr(tmp_path):
    project = tmp_path / "p.meshpaint"
    r = run("fit", CUBE, "--level", "2", "--quiet", "-o", str(project))
    assert r.returncode == 0, r.stderr
    # Cell offsets that decrease (sizes all consistent): VTK's reader reports it on its own.
    bad = tmp_path / "short.vtp"
    bad.write_text('<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1"><PolyData>'
                   '<Piece NumberOfPoints="3" NumberOfPolys="2"><Points><DataArray type="Float32" '
                   'NumberOfComponents="3" format="ascii">0 0 0 1 0 0 0 1 0</DataArray></Points><Polys>'
                   '<DataArray type="Int32" Name="connectivity" format="ascii">0 1 2</DataArray>'
                   '<DataArray type="Int32" Name="offsets" format="ascii">4 3</DataArray></Polys></Piece>'
                   '</PolyData></VTKFile>\n')
    r = run("transfer", str(project), "--to", str(bad), "-o", str(tmp_path / "out.vtp"))
    assert r.returncode == 2
    one_line(r)
    # The same run with the libraries' messages let through shows what was kept back.
    r = run("transfer", str(project), "--to", str(bad), "-o", str(tmp_path / "out.vtp"),
            env={"MESHPAINT_LIBRARY_MESSAGES": "1"})
    assert "vtkXMLPolyDataReader" in r.stderr


@pytest.mark.parametrize("value", ["-1", "+5M", " 5M", "5X", "0", "5m", "1.5G", "99999999999999999999"])
def test_invalid_device_memory_caps_are_refused(value):
    r = run("info", CUBE, env={"MESHPAINT_DEVICE_MEMORY": value})
    assert r.returncode == 2, r.stdout
    assert "MESHPAINT_DEVICE_MEMORY must be a size" in one_line(r)


def test_a_huge_unknown_key_is_quoted_in_part(tmp_path):
    key = "k" * (10 << 20)
    script = tmp_path / "s.json"
    script.write_text(json.dumps({"strokes": [{"tool": "paint", "points": [[0, 0, 0]], key: 1}]}))
    r = run("paint", CUBE, "--strokes", str(script), "-o", str(tmp_path / "out"))
    assert r.returncode == 2
    line = one_line(r)
    assert len(line) < 600, line[:600]
    assert "(10485760 bytes)" in line
    script.write_text(json.dumps({key: 1, "strokes": []}))
    r = run("paint", CUBE, "--strokes", str(script), "-o", str(tmp_path / "out"))
    assert r.returncode == 2 and len(one_line(r)) < 600


def test_a_key_with_a_line_break_stays_on_one_line(tmp_path):
    script = tmp_path / "s.json"
    script.write_text(json.dumps({"strokes": [{"tool": "paint", "points": [[0, 0, 0]], "a\nb": 1}]}))
    r = run("paint", CUBE, "--strokes", str(script), "-o", str(tmp_path / "out"))
    assert r.returncode == 2
    assert "a\\x0ab" in one_line(r)


# Limits (KiB) that stop the run at different points on this kind of machine:
# the OpenCL driver's start, host allocations, the device's buffers.
@pytest.mark.parametrize("kib", [300000, 500000, 700000, 1000000, 2000000])
def test_low_memory_is_one_line_never_an_abort(kib, tmp_path):
    if os.environ.get("MESHPAINT_SANITIZED") == "1":
        pytest.skip("AddressSanitizer reserves terabytes of address space: no build with it runs under ulimit -v")
    if subprocess.run(["sh", "-c", "ulimit -v %d" % kib], capture_output=True).returncode != 0:
        pytest.skip("cannot set ulimit -v %d here" % kib)
    # In a subshell, as a user would: only the command runs under the limit.
    r = subprocess.run(["sh", "-c", 'ulimit -v %d && exec "$@"' % kib, "sh", BIN, "paint",
                        os.path.join(SCANS, "bunny00.off"), "--strokes", STROKES, "--level", "3", "--quiet",
                        "-o", str(tmp_path / "out")], capture_output=True, text=True, timeout=600)
    if r.returncode == 0:
        assert r.stderr == "", r.stderr
        return
    assert r.returncode in (2, 3), r.stderr[:3000]
    line = one_line(r)
    assert "memory" in line, line


def stroke_count():
    with open(STROKES) as f:
        return len(json.load(f)["strokes"])


def test_progress_is_plain_lines_when_stderr_is_not_a_terminal(tmp_path):
    out = tmp_path / "painted"
    r = run("paint", CUBE, "--strokes", STROKES, "-o", str(out))
    assert r.returncode == 0, r.stderr
    lines = r.stderr.splitlines()
    assert all(line.startswith("meshpaint paint: ") for line in lines), r.stderr
    assert "\r" not in r.stderr and "\x1b" not in r.stderr
    assert any(re.fullmatch(r"meshpaint paint: painting %d strokes: 100%% \([0-9.]+ s\)" % stroke_count(), line)
               for line in lines), r.stderr
    assert any(re.fullmatch(r"meshpaint paint: writing %s: 100%% \([0-9.]+ s\)" % re.escape(str(out)), line)
               for line in lines), r.stderr

    r = run("fit", CUBE, "--level", "2", "--passes", "2", "-o", str(tmp_path / "p.meshpaint"))
    assert r.returncode == 0, r.stderr
    for k in (1, 2):
        shown = [line for line in r.stderr.splitlines() if re.match(r"meshpaint fit: pass %d of 2: \d+%%" % k, line)]
        # Lines on the way (at most one a second) say the time left; the last one the time taken.
        assert re.fullmatch(r"meshpaint fit: pass %d of 2: 100%% \([0-9.]+ s\)" % k, shown[-1]), r.stderr
        for line in shown[:-1]:
            assert re.fullmatch(r"meshpaint fit: pass \d of 2: \d+% \(\d+:\d\d left\)", line), line


def test_transfer_and_demo_show_progress(tmp_path):
    project = tmp_path / "p.meshpaint"
    r = run("paint", CUBE, "--strokes", STROKES, "--save", str(project), "--quiet")
    assert r.returncode == 0, r.stderr
    for args, finished in [
        (["transfer", str(project), "--to", CUBE, "-o", str(tmp_path / "t.vtp")],
         r"meshpaint transfer: transferring onto .*cube\.obj: 100% \([0-9.]+ s\)"),
        (["demo", CUBE, "--level", "2", "-o", str(tmp_path / "demo")],
         r"meshpaint demo: subdividing .*cube\.obj to level 2: 100% \([0-9.]+ s\)"),
    ]:
        r = run(*args)
        assert r.returncode == 0, r.stderr
        assert any(re.fullmatch(finished, line) for line in r.stderr.splitlines()), r.stderr
        r = run(*args, "--quiet")
        assert r.returncode == 0, r.stderr
        assert r.stderr == ""


@pytest.mark.parametrize("command", [
    ["paint", CUBE, "--strokes", STROKES, "-o", "{tmp}/painted"],
    ["fit", CUBE, "--level", "2", "-o", "{tmp}/p.meshpaint"],
    ["subdivide", CUBE, "--level", "3", "-o", "{tmp}/s.vtp"],
])
def test_quiet_prints_no_progress(command, tmp_path):
    args = [a.format(tmp=tmp_path) for a in command]
    r = run(*args)
    assert r.returncode == 0 and "100%" in r.stderr, r.stderr
    r = run(*args, "--quiet")
    assert r.returncode == 0, r.stderr
    # warnings stay (fit's cube misses its error bounds: a cube's corners are sharp)
    assert all(": warning: " in line for line in r.stderr.splitlines()), r.stderr


def shown_on_a_terminal(args):
    """What `meshpaint ARGS` draws on a terminal's stderr; its exit status."""
    pty = pytest.importorskip("pty")
    master, slave = pty.openpty()
    try:
        p = subprocess.Popen([BIN, *args], stdout=subprocess.PIPE, stderr=slave, env=dict(os.environ, TERM="xterm"))
        os.close(slave)
        p.communicate(timeout=600)
        shown = b""
        while True:
            try:
                chunk = os.read(master, 65536)
            except OSError:  # EIO: the terminal's other end is closed and drained
                break
            if not chunk:
                break
            shown += chunk
    finally:
        os.close(master)
    return shown.decode(), p.returncode


def test_progress_is_a_bar_on_a_terminal(tmp_path):
    text, status = shown_on_a_terminal(["subdivide", CUBE, "--level", "3", "-o", str(tmp_path / "s.vtp")])
    assert status == 0
    # Redrawn in place: a bar with the percentage and the time left, then the line finished.
    assert re.search(r"\rmeshpaint subdivide: level 3 into .*s\.vtp \[[#.]{30}\] \d+% (--:--|\d+:\d\d) left\x1b\[K",
                     text), repr(text)
    assert re.search(r"\rmeshpaint subdivide: level 3 into .*s\.vtp: 100% \([0-9.]+ s\)\x1b\[K", text), repr(text)


def test_the_writing_bar_moves_as_files_are_written(tmp_path):
    # The femur at level 4 writes for seconds: the bar moves between files.
    strokes = tmp_path / "none.json"
    strokes.write_text('{"strokes": []}')
    femur = os.path.join(SCANS, "femur.off")
    text, status = shown_on_a_terminal(["paint", femur, "--strokes", str(strokes), "--level", "4",
                                        "-o", str(tmp_path / "out")])
    assert status == 0, text
    assert re.search(r"\rmeshpaint paint: writing .*out \[[#.]{30}\] [1-9]\d?% ", text), repr(text)


def test_docs_show_the_usage_text_as_printed():
    with open(os.path.join(SOURCE, "docs", "cli.md")) as f:
        doc = f.read()
    block = re.search(r"\n```\n(usage: meshpaint COMMAND \[ARGS\]\n.*?)```", doc, re.S).group(1)
    assert run("help").stdout == block
