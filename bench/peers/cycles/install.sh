#!/usr/bin/env bash
# Installs Blender (for Cycles 3.4) from the distribution's packages when `blender` is missing.
# Not part of scripts/setup.sh: only bench/peers/cornell_compare.sh needs it (about a minute, +626 MiB).
set -euo pipefail
if command -v blender >/dev/null 2>&1; then
  echo "blender already installed: $(command -v blender)"
  exit 0
fi
SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq || true
$SUDO apt-get install -y --no-install-recommends blender
blender -b --factory-startup --version 2>/dev/null | head -1
