#!/usr/bin/env bash
# Installs what is missing: Debian packages (when root and apt-get exist) and npm packages.
# Usage: scripts/setup.sh runtime|test|bench [system|packages]
#   system: only the Debian packages the native and wasm builds need; packages: only npm's and,
#   for test, the browsers (Debian's) and Python's. Both when not given. npm test builds while
#   the packages part installs.
set -euo pipefail
cd "$(dirname "$0")/.."
mode="${1:-runtime}"
part="${2:-all}"
case "$part" in
  all | system | packages) ;;
  *)
    echo "setup: unknown part '$part' (system or packages)" >&2
    exit 2
    ;;
esac

need_cmd=()  # commands or files that must exist
pkgs=()      # Debian packages providing them
want() { if ! command -v "$1" >/dev/null 2>&1; then need_cmd+=("$1"); pkgs+=("$2"); fi; }
want_file() { if [ ! -e "$1" ]; then need_cmd+=("$1"); pkgs+=("$2"); fi; }

# Installs the Debian packages asked for by want/want_file, if any.
install_wanted() {
  if [ ${#pkgs[@]} -gt 0 ]; then
    # shellcheck disable=SC2207
    uniq_pkgs=($(printf '%s\n' "${pkgs[@]}" | sort -u))
    cmd="apt-get update && apt-get install -y ${uniq_pkgs[*]}"
    echo "setup: missing ${need_cmd[*]}; installing Debian packages: ${uniq_pkgs[*]}"
    if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
      if ! (export DEBIAN_FRONTEND=noninteractive; apt-get update -q && apt-get install -y -q "${uniq_pkgs[@]}"); then
        echo "setup: could not install the packages. Run this yourself, then try again:" >&2
        echo "  sudo sh -c '$cmd'" >&2
        exit 1
      fi
    else
      echo "setup: these Debian packages are needed and I cannot install them (not root or no apt-get)." >&2
      echo "Run this, then try again:" >&2
      echo "  sudo sh -c '$cmd'" >&2
      exit 1
    fi
  fi
  need_cmd=()
  pkgs=()
}

# What the builds need (npm test builds while the packages part installs the rest).
system_packages() {
  want emcc emscripten
  want_file /usr/include/eigen3/Eigen/Core libeigen3-dev
  if [ "$mode" = test ] || [ "$mode" = bench ]; then
    # bench: the native build of build/native (its CMake project also configures the tests).
    want cmake cmake
    want ninja ninja-build
    want g++ g++  # its C++ library; the compiler is clang++-14 (solver-cpp/CMakeLists.txt)
    want clang++-14 clang-14
    want_file /usr/include/gtest/gtest.h libgtest-dev
  fi
  if [ "$mode" = test ]; then
    want clang-format clang-format
    # Debian's Python with venv (ensurepip), for Pixar's USD reader (usd-core) in build/usd-venv
    if ! /usr/bin/python3 -c 'import ensurepip, venv' >/dev/null 2>&1; then
      need_cmd+=("python3 -m venv"); pkgs+=(python3-venv)
    fi
  fi
  install_wanted
}

# The browsers the tests run, which no build needs.
browser_packages() {
  if [ -n "${CHROMIUM_PATH:-}" ]; then  # a Chromium of your choice runs both
    if [ ! -x "$CHROMIUM_PATH" ]; then
      echo "setup: CHROMIUM_PATH=$CHROMIUM_PATH is not an executable; unset it to use Debian's Chromium" >&2
      exit 1
    fi
  else
    want_file /usr/bin/chromium chromium  # the CLI's render command (tests/unit/cliRender)
    # the browser tests' browser (playwright.config.ts)
    want_file /usr/lib/chromium/chromium-headless-shell chromium-headless-shell
  fi
  install_wanted
}

# python_venv DIR CHECK SPEC NOTE: a virtual environment DIR with pip's SPEC in it, made unless
# `python -c CHECK` already succeeds there.
python_venv() {
  local venv="$1" check="$2" spec="$3" note="$4"
  if "$venv/bin/python" -c "$check" >/dev/null 2>&1; then return 0; fi
  echo "setup: creating $venv with $spec (pip install $spec, from PyPI${note:+; $note})"
  rm -rf "$venv"
  mkdir -p "$(dirname "$venv")"
  /usr/bin/python3 -m venv "$venv"
  if ! "$venv/bin/pip" install --disable-pip-version-check -q "$spec"; then
    echo "setup: could not install $spec into $venv (pip install $spec${note:+; $note})." >&2
    exit 1
  fi
  "$venv/bin/python" -c "$check"
}

packages() {
  major=$(node -p 'process.versions.node.split(".")[0]')
  if [ "$major" -lt 20 ]; then
    echo "setup: Node.js 20 or newer is needed (found $(node -v))." >&2
    exit 1
  fi

  if ! node scripts/lock-installed.mjs; then
    # npm ci installs exactly what package-lock.json pins and never rewrites it (npm install may).
    echo "setup: installing npm packages (npm ci, from package-lock.json)"
    npm ci --no-audit --no-fund
  fi

  if [ "$mode" = test ]; then
    browser_packages
    # Pixar's USD reader checks the .usda export (tests/usd/check_usd.py, run by
    # tests/unit/usdExport.test.ts): usd-core from PyPI in a virtual environment of its own.
    python_venv build/usd-venv 'import pxr.Usd' usd-core ""
    # Blender's Python module (bpy, PyPI) imports the .usda export as Blender does
    # (tests/usd/check_blender.py) and exports the glTF heads Open head is tested on
    # (tests/usd/blender_gltf_head.py): a virtual environment of its own (bpy pins its Python and numpy).
    # The version the tests were written against; its wheels are for CPython 3.11.
    python_venv build/bpy-venv \
      'import importlib.util, sys; sys.exit(importlib.util.find_spec("bpy") is None)' bpy==5.0.1 \
      "about 370 MB; it needs CPython 3.11 on x86-64 Linux or macOS/Windows"
  fi
}

if [ "$part" != packages ]; then system_packages; fi
if [ "$part" != system ]; then packages; fi
