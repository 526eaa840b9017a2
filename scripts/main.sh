#!/usr/bin/env bash
# The main job: installs what is missing, builds, and writes the NREL 5MW Campbell diagram
# (0–15 rpm, 36 azimuths per speed, multiblade coordinates) under reports/nrel5mw/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
build/whirl campbell cases/nrel5mw/Main_Onshore.fst --rpm 0:0.5:15 --azimuths 36 --max-freq 3.2 --out reports/nrel5mw
