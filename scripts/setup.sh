#!/usr/bin/env bash
# Idempotent setup for a fresh Debian/Ubuntu machine: Debian packages, .venv with CPython 3.11,
# the Debian OpenVDB binding linked into it, dmdvox installed editable with its dev extras, and
# numba's kernel cache warmed (python -m dmdvox.warm).
# Usage: scripts/setup.sh [--with-tools]   (--with-tools also installs the slicers that the
# sample generators use; Chromium, which the report's browser test drives, is always installed)
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo"

packages=(python3-openvdb python3-venv python3-dev libopenvdb-tools chromium)
if [[ "${1:-}" == "--with-tools" ]]; then
    packages+=(prusa-slicer slic3r cura-engine)
fi

missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
    if [[ $(id -u) -eq 0 ]]; then
        echo "setup: installing Debian packages: ${missing[*]}" >&2
        apt-get update -qq
        DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}" >&2
    else
        echo "setup: missing Debian packages: ${missing[*]}" >&2
        echo "setup: run: sudo apt-get install -y ${missing[*]}" >&2
        exit 2
    fi
fi

# The Debian binding is built for the system CPython 3.11 ABI; any CPython 3.11 can load it.
python=""
for candidate in /usr/bin/python3.11 /usr/bin/python3 python3.11 python3; do
    if command -v "$candidate" >/dev/null 2>&1 &&
        "$candidate" -c 'import sys; sys.exit(sys.version_info[:2] != (3, 11))' 2>/dev/null; then
        python="$(command -v "$candidate")"
        break
    fi
done
if [[ -z "$python" ]]; then
    echo "setup: no CPython 3.11 found (python3-openvdb is built for 3.11); install python3.11" >&2
    exit 2
fi

if [[ ! -x .venv/bin/python ]] || ! .venv/bin/python -c 'import sys; sys.exit(sys.version_info[:2] != (3, 11))'; then
    rm -rf .venv
    "$python" -m venv .venv
fi

site="$(.venv/bin/python -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')"
binding="$(ls /usr/lib/python3/dist-packages/pyopenvdb.cpython-311-*.so 2>/dev/null | head -n1 || true)"
if [[ -n "$binding" ]]; then
    ln -sf "$binding" "$site/$(basename "$binding")"
fi

export PIP_CONSTRAINT="$repo/scripts/constraints.txt"
export PIP_DISABLE_PIP_VERSION_CHECK=1
stamp=".venv/.dmdvox-installed"
if [[ ! -f "$stamp" || pyproject.toml -nt "$stamp" || scripts/constraints.txt -nt "$stamp" ]]; then
    .venv/bin/python -m pip install -q --upgrade pip >&2
    .venv/bin/python -m pip install -q -e ".[dev]" >&2
    touch "$stamp"
fi
.venv/bin/python -c 'import numpy, sys; sys.exit(int(numpy.__version__.split(".")[0]) >= 2)' || {
    echo "setup: numpy >= 2 got into .venv; pyopenvdb needs numpy < 2" >&2
    exit 1
}
.venv/bin/python -c 'from dmdvox.vdb import openvdb' || exit 1

# numba compiles each kernel on its first call (a minute for the demo's first simulate) and
# caches the machine code beside the sources: compile them here, once, so that the first
# command after setup runs warm. Again only when a source or the installed packages changed
# (a pull, an upgrade): numba discards a kernel's cache when its source file changes.
warm=".venv/.dmdvox-warm"
if [[ ! -f "$warm" || "$stamp" -nt "$warm" || -n "$(find dmdvox -name '*.py' -newer "$warm" -print -quit)" ]]; then
    echo "setup: compiling dmdvox's kernels (a few minutes on a fresh install; cached for every later run)" >&2
    if .venv/bin/python -m dmdvox.warm; then
        touch "$warm"
    else
        echo "setup: warning: warming the kernel cache failed (above); the first commands will compile instead" >&2
    fi
fi
echo "setup: ready (.venv/bin/dmdvox)" >&2
