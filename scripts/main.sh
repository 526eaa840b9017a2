#!/usr/bin/env bash
# The main job: installs what is missing, builds, and writes the NREL 5MW Campbell diagrams under reports/:
# - `import whirl` for python3 (scripts/install-python.sh);
# - reports/nrel5mw/: structural, 0–15 rpm, 36 azimuths per speed, multiblade coordinates;
# - reports/nrel5mw_aero/: aeroelastic (AeroDyn BEMT, frozen wake) along the wind, 3–25 m/s, each
#   point trimmed (rotor speed below rated, pitch above), with the steady performance table, the
#   interactive report campbell.html (mode shapes, docs/user/mode-shapes.md) and HAWCStab2's .cmb/.amp/.opt;
# - reports/nrel5mw_aero_ua/: the same with the blade elements' unsteady-airfoil states (the airfoil files'
#   UA data, HGM model), the aerodynamic roots apart in campbell_aero.csv (docs/theory/unsteady-aero.md);
# - reports/nrel5mw_aero_ua_dbemt/: the same with Øye's dynamic inflow as well (DBEMT_Mod 3, the deck's tau1_const);
# - reports/nrel5mw_aero_models/: the three side by side (campbell_side_by_side.png, one column per model) and
#   their first tower, flap and edge modes tabulated (aero_models.csv);
# - reports/nrel5mw_rosco/: with ROSCO's controller, open and closed loop (below);
# - reports/oc3_hywind_rosco/: the floating NREL 5MW with its ROSCO controller, closed loop (below).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
bash scripts/install-python.sh  # `import whirl` (docs/user/python.md)
build/whirl campbell cases/nrel5mw/Main_Onshore.fst --rpm 0:0.5:15 --azimuths 36 --max-freq 3.2 --out reports/nrel5mw
build/whirl steady cases/nrel5mw/Main_Aero.fst --wind 3:1:25 --out reports/nrel5mw_aero
build/whirl campbell cases/nrel5mw/Main_Aero.fst --wind 3:1:25 --azimuths 36 --max-freq 3.2 --out reports/nrel5mw_aero \
  --html --format hawcstab2
build/whirl campbell cases/nrel5mw/Main_Aero.fst --set AFAeroMod=2 --set UAMod=4 --unsteady-aero --wind 3:1:25 \
  --azimuths 36 --max-freq 3.2 --out reports/nrel5mw_aero_ua
build/whirl campbell cases/nrel5mw/Main_Aero.fst --set AFAeroMod=2 --set UAMod=4 --set WakeMod=2 --set DBEMT_Mod=3 \
  --unsteady-aero --wind 3:1:25 --azimuths 36 --max-freq 3.2 --out reports/nrel5mw_aero_ua_dbemt
build/whirl report reports/nrel5mw_aero reports/nrel5mw_aero_ua reports/nrel5mw_aero_ua_dbemt --side-by-side \
  --label "quasi-steady" --label "UA" --label "UA + DBEMT" --max-freq 3.2 --out reports/nrel5mw_aero_models
# The NREL 5MW with ROSCO's controller (cases/nrel5mw/Main_ROSCO.fst): the schedule it settles at along
# the wind, the open-loop Campbell diagram along that schedule, and the closed loop with the controller
# (reports/nrel5mw_rosco/closed_loop/: closed-loop Campbell, open vs closed side by side in
# closed_loop.png, the loop margins in margins.csv; docs/user/closed-loop.md).
build/whirl steady cases/nrel5mw/Main_ROSCO.fst --wind 3:1:25 --out reports/nrel5mw_rosco
build/whirl campbell cases/nrel5mw/Main_ROSCO.fst --wind 3:1:25 --azimuths 36 --max-freq 3.2 --out reports/nrel5mw_rosco
build/whirl campbell cases/nrel5mw/Main_ROSCO.fst --wind 3:1:25 --azimuths 36 --max-freq 3.2 --closed-loop \
  --out reports/nrel5mw_rosco/closed_loop
# The NREL 5MW on the OC3-Hywind spar with a floating ROSCO controller (floating feedback Fl_Mode 1;
# cases/oc3_hywind/rosco/README.md): closed loop along the wind (reports/oc3_hywind_rosco/closed_loop/)
# and a wind step, nonlinear against the linear closed loop (reports/oc3_hywind_rosco/step_16mps/).
build/whirl campbell cases/oc3_hywind/Main_ROSCO.fst --set RdtnMod=0 --wind 3:1:25 --azimuths 36 --max-freq 3.2 \
  --closed-loop --out reports/oc3_hywind_rosco/closed_loop
build/whirl verify cases/oc3_hywind/Main_ROSCO.fst --set RdtnMod=0 --closed-loop --wind 16 --tmax 60 \
  --output GenSpeed --output PtfmPitch --output TTDspFA --out reports/oc3_hywind_rosco/step_16mps
