#!/usr/bin/env bash
# Install Kratos Multiphysics and its DEMApplication (PyPI wheels, CPython 3.11) into their own venv
# PREFIX_ROOT/kratos-<version>/ (default $HARNESS_ENGINES_DIR, else /opt/harness/engines), where harness finds them
# (harness/engines/kratos: the prefix's bin/python is the engine). Never on the project venv's path: Kratos brings its
# own numpy. Idempotent: a prefix whose python imports the DEMApplication at this version is skipped.
# Usage: tools/install_kratos.sh [PREFIX_ROOT]
set -euo pipefail
ROOT="${1:-${HARNESS_ENGINES_DIR:-/opt/harness/engines}}"
VERSION=10.4.4
PYTHON="${KRATOS_PYTHON:-python3.11}"
prefix="$ROOT/kratos-$VERSION"
check='import importlib.metadata as m, KratosMultiphysics.DEMApplication
print("kratos-dem", m.version("KratosDEMApplication"))'

installed() {
  [ -x "$prefix/bin/python" ] &&
    OMP_NUM_THREADS=1 "$prefix/bin/python" -c "$check" 2>/dev/null | grep -x "kratos-dem $VERSION" >/dev/null
}

if installed; then
  echo "install_kratos: $prefix is complete" >&2
  exit 0
fi
if ! command -v "$PYTHON" >/dev/null 2>&1; then
  echo "install_kratos: no $PYTHON (the Kratos wheels are CPython 3.11)" >&2
  exit 1
fi
mkdir -p "$ROOT"
echo "install_kratos: installing KratosMultiphysics $VERSION and KratosDEMApplication $VERSION into $prefix" >&2
[ -x "$prefix/bin/python" ] || "$PYTHON" -m venv "$prefix"
"$prefix/bin/python" -m pip install -q --disable-pip-version-check "KratosMultiphysics==$VERSION" \
  "KratosDEMApplication==$VERSION" 2>&1 | grep -v '^WARNING: Location' >&2 || true
installed || { echo "install_kratos: $prefix does not import KratosMultiphysics.DEMApplication $VERSION" >&2; exit 1; }
echo "install_kratos: $prefix runs Kratos $VERSION; disk: $(du -sh "$prefix" | cut -f1)" >&2
