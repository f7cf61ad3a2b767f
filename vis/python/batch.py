"""Batches: the same stroke script over many scans, one Dask task per scan.

    python3 -m meshpaint.batch SCAN... --strokes S.json [--fit] [--labels labels.json]
        [--workers N | --scheduler ADDRESS] [--level L] [--timeout S] [--meshpaint PATH] [--quiet] -o DIR

From Python: rows = meshpaint.batch.run(scans, strokes="S.json", output="DIR").
docs/batch.md describes the outputs, the summary and the exit codes.
"""
import argparse
import csv
import io
import json
import os
import sys
import uuid

from . import Error
from . import scan_job
from .scan_job import COLUMNS, process_scan, write_atomically

SUMMARY = "summary.csv"

#: Exit codes of `python3 -m meshpaint.batch`.
EXIT_OK, EXIT_INPUT, EXIT_RESOURCE, EXIT_SCANS_FAILED = 0, 2, 3, 4

#: The default time limit of one scan, in seconds.
DEFAULT_TIMEOUT = 3600.0


def scan_names(scans):
    """The folder name of each scan under DIR: its file name without extension, made unique in order."""
    taken = {scan_job.LOGS, SUMMARY}
    names = []
    for scan in scans:
        stem = os.path.splitext(os.path.basename(scan))[0] or "scan"
        name, n = stem, 1
        while name in taken or name.startswith("."):
            n += 1
            name = f"{stem.lstrip('.') or 'scan'}-{n}"
        taken.add(name)
        names.append(name)
    return names


def _json_file(path, what):
    """Checks that a file is readable JSON, so a typo stops the batch before any scan runs."""
    try:
        with open(path) as f:
            json.load(f)
    except OSError as e:
        raise Error(f"cannot read {what} '{path}': {e.strerror}") from None
    except ValueError as e:
        raise Error(f"{what} '{path}' is not JSON: {e}") from None


def summary_csv(rows):
    """The summary as CSV text: a header of COLUMNS, one row per scan, empty where there is no value."""
    text = io.StringIO()
    writer = csv.DictWriter(text, fieldnames=COLUMNS, lineterminator="\n")
    writer.writeheader()
    for row in rows:
        writer.writerow({k: "" if row.get(k) is None else row[k] for k in COLUMNS})
    return text.getvalue()


def _local_client(workers):
    """A LocalCluster of `workers` processes with one thread each: one scan at a time per process."""
    from distributed import Client, LocalCluster

    cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None)
    return Client(cluster), cluster


def run(scans, strokes, output, *, fit=False, labels=None, level=None, client=None, workers=None,
        timeout=DEFAULT_TIMEOUT, executable=None, progress=None):
    """Runs fit (with fit=True), the stroke script, stats and transfer on every scan, one Dask task each.

    scans: paths of the scans; strokes: the stroke script's path; output: the
    folder of the results (created). client: a distributed.Client to run on
    (an existing cluster); without one, a LocalCluster of `workers` processes
    (default: one per CPU) is started and closed. timeout: seconds one scan
    may take (None or 0: no limit). executable: the meshpaint program as the
    workers see it (default: beside this package, else on PATH). progress:
    called with each row as its scan ends.

    Returns the summary rows, in the order of `scans`, as dicts with the keys
    of COLUMNS; also written to output/summary.csv. Raises meshpaint.Error
    for bad arguments, before any scan runs; failing scans only fail their row.
    """
    scans = [os.path.abspath(os.fspath(s)) for s in scans]
    if not scans:
        raise Error("no scans given")
    strokes = os.path.abspath(os.fspath(strokes))
    _json_file(strokes, "stroke script")
    if labels is not None:
        labels = os.path.abspath(os.fspath(labels))
        _json_file(labels, "labels file")
    if level is not None and not (isinstance(level, int) and 1 <= level <= 12):
        raise Error(f"level must be an integer from 1 to 12, not {level!r}")
    if timeout is not None and not timeout >= 0:
        raise Error(f"timeout must be 0 (none) or a number of seconds, not {timeout!r}")
    if workers is not None and (client is not None or not (isinstance(workers, int) and workers >= 1)):
        raise Error("workers must be a positive integer, and is not used with a client")
    output = os.path.abspath(os.fspath(output))
    try:
        os.makedirs(output, exist_ok=True)
    except OSError as e:
        raise Error(f"cannot create the output folder '{output}': {e.strerror}") from None

    names = scan_names(scans)
    cluster = None
    if client is None:
        client, cluster = _local_client(workers or os.cpu_count() or 1)
    try:
        rows = _run_on(client, scans, names, output, progress,
                       dict(strokes=strokes, fit=fit, labels=labels, level=level, timeout=timeout,
                            executable=executable))
    finally:
        if cluster is not None:
            client.close()
            cluster.close()
    return rows


def _run_on(client, scans, names, output, progress, options):
    from distributed import as_completed

    futures = {}
    batch_id = uuid.uuid4().hex[:12]
    for index, (scan, name) in enumerate(zip(scans, names)):
        # A key of its own per batch: a re-run must run again, not meet a result the cluster remembers.
        future = client.submit(process_scan, scan, name, output, pure=False, retries=0,
                               key=f"meshpaint-scan-{name}-{batch_id}", **options)
        futures[future] = index
    rows = [None] * len(scans)
    for future in as_completed(futures):
        index = futures[future]
        try:
            row = future.result()
        except Exception as e:  # the worker itself died or could not run the task
            row = dict.fromkeys(COLUMNS)
            message = str(e).strip().splitlines()[0] if str(e).strip() else type(e).__name__
            row.update(scan=names[index], path=scans[index], status="failed",
                       error=f"meshpaint.batch: {type(e).__name__}: {message}")
        rows[index] = row
        # Rewritten as each scan ends, so a long batch shows its progress and a
        # killed one leaves the scans it finished.
        write_atomically(os.path.join(output, SUMMARY), summary_csv([r for r in rows if r is not None]))
        if progress is not None:
            progress(row)
    return rows


def _parser():
    p = argparse.ArgumentParser(
        prog="python3 -m meshpaint.batch",
        description="Runs fit (optional), a stroke script, stats and transfer on every scan, "
                    "one Dask task per scan. Outputs: DIR/<scan>/, DIR/summary.csv, DIR/logs/.")
    p.add_argument("scans", nargs="+", metavar="SCAN", help="scans (.obj .off .ply .stl)")
    p.add_argument("--strokes", required=True, metavar="S.json", help="the stroke script (docs/strokes.md)")
    p.add_argument("--fit", action="store_true", help="fit a project to each scan first (meshpaint fit)")
    p.add_argument("--labels", metavar="labels.json", help="label classes kept in each project")
    p.add_argument("--level", type=int, metavar="L", help="fitting or painting level, 1 to 12")
    where = p.add_mutually_exclusive_group()
    where.add_argument("--workers", type=int, metavar="N", help="local worker processes (default: one per CPU)")
    where.add_argument("--scheduler", metavar="ADDRESS", help="an existing Dask scheduler, e.g. tcp://HOST:8786")
    p.add_argument("--timeout", type=float, default=DEFAULT_TIMEOUT, metavar="S",
                   help=f"seconds one scan may take, 0: no limit (default {DEFAULT_TIMEOUT:g})")
    p.add_argument("--meshpaint", metavar="PATH", help="the meshpaint program on the workers")
    p.add_argument("--quiet", action="store_true", help="no line per finished scan on stderr")
    p.add_argument("-o", dest="output", required=True, metavar="DIR", help="output folder")
    return p


def _quiet_cluster_logs():
    """The command's stderr carries its own lines only. Dask's warnings on a
    loaded machine (an event loop slow to answer, a close that timed out
    after every result was in) are about the cluster, not the scans: kept
    to errors, in this process and in the workers it starts (which read
    the environment). asyncio's report of a future nobody awaited, left by
    such a close, is dropped."""
    import logging

    os.environ.setdefault("DASK_LOGGING__DISTRIBUTED", "error")
    logging.getLogger("distributed").setLevel(logging.ERROR)
    logging.getLogger("asyncio").setLevel(logging.CRITICAL)


def main(argv=None):
    parser = _parser()
    # argparse's own errors: one line and exit 2, as the command line's.
    parser.error = lambda message: _fail(EXIT_INPUT, message)
    args = parser.parse_args(argv)
    _quiet_cluster_logs()
    total = len(args.scans)
    done = []

    def report(row):
        done.append(row)
        if not args.quiet:
            what = "ok" if row["status"] == "ok" else f"failed: {row['error']}"
            print(f"meshpaint.batch: [{len(done)}/{total}] {row['scan']} {what} ({row['seconds']:g} s)",
                  file=sys.stderr, flush=True)

    client = None
    if args.scheduler:
        from distributed import Client

        try:
            client = Client(args.scheduler)  # waits as long as Dask's distributed.comm.timeouts.connect
        except (OSError, TimeoutError, ValueError) as e:
            _fail(EXIT_RESOURCE, f"cannot reach the scheduler {args.scheduler}: {e}".splitlines()[0])
    try:
        rows = run(args.scans, args.strokes, args.output, fit=args.fit, labels=args.labels, level=args.level,
                   client=client, workers=args.workers, timeout=args.timeout, executable=args.meshpaint,
                   progress=report)
    except Error as e:
        _fail(EXIT_INPUT, str(e))
    finally:
        if client is not None:
            client.close(timeout=60)
    failed = sum(row["status"] != "ok" for row in rows)
    summary = os.path.join(args.output, SUMMARY)
    if failed:
        print(f"meshpaint.batch: {failed} of {total} scans failed (see {summary})", file=sys.stderr)
        return EXIT_SCANS_FAILED
    if not args.quiet:
        print(f"meshpaint.batch: {total} scans done ({summary})", file=sys.stderr)
    return EXIT_OK


def _fail(code, message):
    print(f"meshpaint.batch: {message}", file=sys.stderr)
    sys.exit(code)


if __name__ == "__main__":
    # Run as `python3 -m meshpaint.batch`: call the package's module, so the
    # tasks sent to the workers name meshpaint.batch, not __main__.
    from meshpaint import batch as _batch

    sys.exit(_batch.main())
