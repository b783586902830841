"""kappa.batch: the same outputs as `kappa batch`, skipping, shards and failures."""
import os

import kappa
from conftest import run_kappa, torus, write_obj

LINES = [
    "-          out/default-0.png --view 0,20 --size 128x96",
    "torus.obj  out/torus-0.png   --view 0,40 --size 128x96 --shading none",
    "-          out/default-1.svg --view 90,20 --size 128x96 --shading none",
    "torus.obj  out/torus.csv",
    "missing.obj out/missing.png --size 128x96",
]


def outputs(folder):
    return {name: open(os.path.join(folder, name), "rb").read() for name in sorted(os.listdir(folder))}


def test_batch_matches_the_command_line_and_skips_what_exists(tmp_path):
    write_obj(tmp_path / "torus.obj", *torus(nu=32, nv=16))
    report = kappa.batch(LINES, base_dir=tmp_path)
    assert (report["jobs"], report["written"], report["skipped"]) == (5, 4, 0)
    assert [(f["line"], f["reason"]) for f in report["failed"]] == [(5, f"{tmp_path}/missing.obj: no such file")]
    assert "5 jobs: 4 written, 0 skipped (output exists), 1 failed" in report["summary"]
    ours = outputs(tmp_path / "out")
    # The command line, from a manifest file in another folder.
    (tmp_path / "cli").mkdir()
    write_obj(tmp_path / "cli" / "torus.obj", *torus(nu=32, nv=16))
    (tmp_path / "cli" / "jobs.txt").write_text("\n".join(LINES) + "\n")
    status, text = run_kappa("batch", "-q", tmp_path / "cli" / "jobs.txt")
    assert status == 1 and "line 5: " in text, text
    assert outputs(tmp_path / "cli" / "out") == ours
    # Again: everything there is skipped.
    again = kappa.batch(str(tmp_path / "cli" / "jobs.txt"))
    assert (again["written"], again["skipped"], len(again["failed"])) == (0, 4, 1)
    assert kappa.gl_context()["contexts_created"] == 1


def test_shards_and_the_manifest_as_read(tmp_path):
    jobs = kappa.read_manifest(LINES, base_dir=tmp_path)
    assert [j["line"] for j in jobs] == [1, 2, 3, 4, 5]
    assert jobs[0]["mesh"] == "" and jobs[1]["mesh"] == str(tmp_path / "torus.obj")
    assert jobs[1]["options"] == ["--view", "0,40", "--size", "128x96", "--shading", "none"]
    write_obj(tmp_path / "torus.obj", *torus(nu=16, nv=8))
    first = kappa.batch(LINES, base_dir=tmp_path, shard=(1, 3))  # meshes: built-in, torus, missing
    assert first["jobs"] == 2 and first["written"] == 2
    assert sorted(os.listdir(tmp_path / "out")) == ["torus-0.png", "torus.csv"]
    try:
        kappa.batch(LINES, shard=(3, 3))
        assert False, "no error"
    except ValueError as e:
        assert str(e) == "shard expects (i, n) with 0 <= i < n, got (3, 3)"
    try:
        kappa.batch(['- "out/x.png'])
        assert False, "no error"
    except ValueError as e:
        assert str(e) == "<lines>:1: unterminated quote"
