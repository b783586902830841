"""scripts/dask_batch.py on a LocalCluster of 2 worker processes: 8 meshes x 4 views, the same bytes as
a serial `kappa batch`, one GL context per worker process."""
import os

import numpy as np

from conftest import run_kappa, torus, write_obj


def write_meshes_and_manifest(folder):
    lines = []
    for m in range(8):
        if m == 0:
            mesh = "-"  # the built-in model
        else:  # tori of different shapes and tessellations
            mesh = f"torus-{m}.obj"
            V, F = torus(R=1.0, r=0.2 + 0.05 * m, nu=16 + 4 * m, nv=8 + 2 * m)
            write_obj(os.path.join(folder, mesh), V * np.float32(1 + 0.1 * m), F)
        for view in range(4):
            lines.append(f"{mesh} out/{m}-{view}.png --view {90 * view + 20},25 --size 128x96 --shading none")
    with open(os.path.join(folder, "jobs.txt"), "w") as f:
        f.write("\n".join(lines) + "\n")
    return os.path.join(folder, "jobs.txt")


def outputs(folder):
    return {name: open(os.path.join(folder, name), "rb").read() for name in sorted(os.listdir(folder))}


def test_dask_batch_equals_the_serial_run(tmp_path):
    from dask.distributed import Client, LocalCluster

    import dask_batch

    serial, parallel = tmp_path / "serial", tmp_path / "dask"
    serial.mkdir(), parallel.mkdir()
    status, text = run_kappa("batch", "-q", write_meshes_and_manifest(serial))
    assert status == 0, text
    manifest = write_meshes_and_manifest(parallel)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            Client(cluster) as client:
        total, reports = dask_batch.run(manifest, client, log=None)
    assert (total["meshes"], total["jobs"], total["written"], total["failed"]) == (8, 32, 32, [])
    assert len(reports) == 8 and all(r["jobs"] == 4 for r in reports)  # one task per mesh
    # Every worker process made one GL context and reused it for all its tasks.
    pids = {r["pid"] for r in reports}
    assert 1 <= len(pids) <= 2 and all(r["contexts_created"] == 1 for r in reports)
    serial_out, dask_out = outputs(serial / "out"), outputs(parallel / "out")
    assert len(dask_out) == 32 and dask_out == serial_out
