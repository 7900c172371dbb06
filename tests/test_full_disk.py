"""A full disk ends a command in one line (exit 3), and damages nothing: every file there is whole, an earlier file
at the same path is intact, no temporary file is left and the output lock is released. The disk is a real tmpfs of
64 KB, mounted in a private mount namespace (unshare) so that neither root nor the host's mounts are needed."""
import json
import shutil
import subprocess
import sys

import pytest

INSPECT = r"""
import fcntl, json, os, subprocess, sys
disk, argv = sys.argv[1], sys.argv[2:]
done = subprocess.run([sys.executable, "-m", "harness", *argv], capture_output=True, text=True)
files, broken, free = {}, [], True
for root, _, names in os.walk(disk):
    for name in names:
        path = os.path.join(root, name)
        files[os.path.relpath(path, disk)] = open(path, "rb").read().decode("utf-8", "replace")
        if name == ".harness.infra.lock":
            with open(path) as handle:
                try:
                    fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
                except BlockingIOError:
                    free = False
print(json.dumps({"code": done.returncode, "err": done.stderr, "files": files, "lock_free": free}))
"""

SETUP = 'mount -t tmpfs -o size=64k tmpfs "$1" && printf "earlier results\\n" > "$1/r.csv" && shift && exec "$@"'


def namespaces_allowed():
    return shutil.which("unshare") is not None and subprocess.run(
        ["unshare", "--user", "--map-root-user", "--mount", "true"], capture_output=True).returncode == 0


pytestmark = pytest.mark.skipif(not namespaces_allowed(), reason="no user and mount namespaces here")


def on_a_full_disk(tmp_path, *argv):
    """What `harness ARGV` leaves on a 64 KB disk mounted at DISK ({disk} in argv), which holds r.csv beforehand."""
    disk = tmp_path / "disk"
    disk.mkdir()
    argv = [a.replace("{disk}", str(disk)) for a in argv]
    done = subprocess.run(["unshare", "--user", "--map-root-user", "--mount", "--", "sh", "-c", SETUP, "sh",
                           str(disk), sys.executable, "-c", INSPECT, str(disk), *argv],
                          capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def said_in_one_line(found):
    lines = found["err"].strip().splitlines()
    return (found["code"] == 3 and len(lines) == 1 and "no space left on the device" in lines[0]
            and "every file is whole" in lines[0] and "Traceback" not in found["err"])


def test_run_on_a_full_disk_leaves_the_earlier_file_whole(tmp_path):
    found = on_a_full_disk(tmp_path, "run", "--model", "hertz-mindlin", "--angles", "0:89:0.5", "-o", "{disk}/r.csv",
                            "--quiet")
    assert said_in_one_line(found), found["err"]
    assert found["files"] == {"r.csv": "earlier results\n"}


def test_compare_on_a_full_disk_keeps_whole_files_and_releases_its_lock(tmp_path):
    import io

    import pandas as pd
    found = on_a_full_disk(tmp_path, "compare", "--model", "hertz-mindlin", "--engines", "reference", "-o",
                           "{disk}/out", "--quiet")
    assert said_in_one_line(found), found["err"]
    assert "finished results were kept" in found["err"]
    assert found["lock_free"] and not [name for name in found["files"] if name.endswith(".tmp")]
    assert found["files"]["r.csv"] == "earlier results\n"
    tables = {name: text for name, text in found["files"].items() if name.startswith("out/") and name.endswith(".csv")}
    assert tables
    for name, text in tables.items():               # each table whole: parsed, every line with every column
        frame = pd.read_csv(io.StringIO(text))
        assert len(frame) > 0 and text.endswith("\n") and not frame.isna().all(axis=1).any(), name
    assert "out/report.html" not in found["files"]
