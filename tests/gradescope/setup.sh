#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image (Ubuntu 22.04 by
# default): the kit's packages, a CMake the kit accepts, and the kit built once, everything but the
# student's files, so that each submission compiles only those (run_autograder --prebuild).
# AUTOGRADER_ROOT moves the whole layout (the kit's own test runs it in a scratch folder, where
# RT_SKIP_PACKAGES=1 leaves the machine's packages alone).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
sudo=""
[ "$(id -u)" = 0 ] || sudo="sudo"
if [ -z "${RT_SKIP_PACKAGES:-}" ]; then
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends \
    cmake ninja-build g++ pkgconf catch2 libglm-dev libstb-dev
fi

# The kit asks for CMake 3.22 (Ubuntu 22.04's). An older image's gets a newer one from pip.
need=3.22
have="$(cmake --version | sed -n 's/^cmake version \([0-9.]*\).*/\1/p')"
if [ "$(printf '%s\n%s\n' "$need" "$have" | sort -V | head -n 1)" != "$need" ]; then
  echo "this image's CMake is $have; the kit needs $need or later: installing one with pip"
  $sudo apt-get install -y -qq --no-install-recommends python3-pip
  $sudo python3 -m pip install --quiet "cmake>=$need"
  hash -r
fi
echo "CMake $(cmake --version | sed -n 's/^cmake version //p')"

start=$SECONDS
bash "$here/run_autograder" --prebuild
echo "the kit was built in $((SECONDS - start)) s: a submission compiles only its own files"
