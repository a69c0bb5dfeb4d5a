#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image: the kit's packages.
set -euo pipefail
sudo=""
[ "$(id -u)" = 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends \
  cmake ninja-build g++ pkgconf catch2 libglm-dev libstb-dev
