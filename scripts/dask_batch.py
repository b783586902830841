#!/usr/bin/env python3
"""Runs a `kappa batch` manifest on Dask distributed: one task per mesh (README, "Batch on a cluster").

    python3 scripts/dask_batch.py jobs.txt                               # this machine, one worker a core
    python3 scripts/dask_batch.py jobs.txt --scheduler tcp://host:8786   # an existing Dask cluster

Each task runs the jobs of one mesh through kappa.batch in a worker process: the mesh is read once,
and every render uses the worker's one GL context (made by its first task, reused by all the
others: kappa.gl_context()). Outputs are byte-identical to `kappa batch jobs.txt`, existing
outputs are skipped (--force rewrites them), failures are listed at the end (exit status 1).
On a cluster, workers need the kappa module (PYTHONPATH or installed) and must see the meshes and
output folders at the same paths as this machine (a shared file system).
"""
import argparse
import os
import sys
import time

import kappa


def quoted(word):
    """A manifest word: double quotes when it holds blanks or quotes."""
    if word and not any(c.isspace() or c in '"#\\' for c in word):
        return word
    return '"' + word.replace("\\", "\\\\").replace('"', '\\"') + '"'


def mesh_tasks(manifest):
    """The manifest's jobs as one list of lines per mesh (paths absolute), with their line numbers."""
    groups = {}
    for job in kappa.read_manifest(os.path.abspath(manifest)):
        words = [job["mesh"] or "-", job["output"], *job["options"]]
        lines, numbers = groups.setdefault(job["mesh"], ([], []))
        lines.append(" ".join(map(quoted, words)))
        numbers.append(job["line"])
    return list(groups.values())


def run_mesh(lines, numbers, skip_existing=True):
    """One task: the jobs of one mesh, in this worker's process (and its GL context)."""
    import kappa  # in the worker

    report = kappa.batch(lines, skip_existing=skip_existing)
    for failure in report["failed"]:
        failure["line"] = numbers[failure["line"] - 1]  # back to the manifest's numbering
    report["pid"] = os.getpid()
    report["contexts_created"] = kappa.gl_context()["contexts_created"]
    return report


def run(manifest, client, skip_existing=True, log=sys.stderr):
    """Runs every mesh's jobs as one task on `client`; returns the merged report and the tasks' reports."""
    from dask.distributed import as_completed

    tasks = mesh_tasks(manifest)
    start = time.monotonic()
    futures = [client.submit(run_mesh, lines, numbers, skip_existing, pure=False) for lines, numbers in tasks]
    reports = []
    for done, future in enumerate(as_completed(futures), 1):
        reports.append(future.result())
        if log:
            elapsed = time.monotonic() - start
            eta = elapsed / done * (len(futures) - done)
            print(f"dask_batch: [{done}/{len(futures)} meshes] ETA {eta:.0f} s", file=log, flush=True)
    total = {key: sum(r[key] for r in reports) for key in ("jobs", "written", "skipped")}
    total["failed"] = sorted((f for r in reports for f in r["failed"]), key=lambda f: f["line"])
    total["seconds"] = time.monotonic() - start
    total["meshes"] = len(tasks)
    return total, reports


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("manifest", help="the jobs, one a line: MESH OUTPUT [OPTIONS...] (README, 'kappa batch')")
    parser.add_argument("--scheduler", help="address of a running Dask scheduler, e.g. tcp://host:8786 "
                        "(default: a local cluster on this machine)")
    parser.add_argument("--workers", type=int, default=os.cpu_count(),
                        help="worker processes of the local cluster (default: one per core)")
    parser.add_argument("--force", action="store_true", help="write every output, even those that exist")
    args = parser.parse_args()

    from dask.distributed import Client, LocalCluster

    if args.scheduler:
        client = Client(args.scheduler)
    else:  # one single-threaded worker process per core: each with its own GL context
        client = Client(LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True))
    with client:
        total, _ = run(args.manifest, client, skip_existing=not args.force)
    minutes = total["seconds"] / 60
    print(f"dask_batch: {total['meshes']} meshes, {total['jobs']} jobs: {total['written']} written, "
          f"{total['skipped']} skipped (output exists), {len(total['failed'])} failed in {total['seconds']:.1f} s "
          f"({total['meshes'] / minutes:.1f} meshes/minute)", file=sys.stderr)
    for f in total["failed"]:
        print(f"  line {f['line']}: {f['output']}: {f['reason']}", file=sys.stderr)
    return 1 if total["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())
