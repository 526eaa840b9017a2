#!/usr/bin/env bash
# Collects the seed corpus of every fuzz harness from cases/, tests/data/ and fuzz/seeds/ into
# DIR/<harness>/ (default build-fuzz/seeds). Copies, not committed: the inputs live where they are.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-build-fuzz/seeds}
rm -rf "$out"
add() {  # add HARNESS FILE...
  local h=$1; shift
  mkdir -p "$out/$h"
  for f in "$@"; do [ -f "$f" ] && cp "$f" "$out/$h/$(echo "$f" | tr / _)"; done
}
add fuzz_case_yaml cases/*/*.yaml
add fuzz_fst cases/nrel5mw/*.fst tests/data/openfast/*/*.fst
add fuzz_elastodyn cases/nrel5mw/*_ElastoDyn.dat tests/data/openfast/rotating-9rpm/ElastoDyn.dat tests/data/openfast/ws03/*_ED.dat \
  tests/data/openfast/decks/certtest/AWT27/Test0[15]_ElastoDyn.dat tests/data/openfast/decks/certtest/UAE_VI/Test09_ElastoDyn.dat
add fuzz_servodyn cases/nrel5mw/*_ServoDyn.dat
add fuzz_ed_tower cases/nrel5mw/*_Tower.dat tests/data/openfast/5MW_Baseline/*_Tower.dat
add fuzz_ed_blade cases/nrel5mw/NRELOffshrBsline5MW_Blade.dat tests/data/openfast/5MW_Baseline/*_Blade.dat
add fuzz_openfast_parse cases/nrel5mw/*.fst cases/nrel5mw/*.dat tests/data/openfast/*/*.fst tests/data/openfast/*/*.dat \
  cases/nrel5mw/aero/*.dat cases/nrel5mw/5MW_Baseline/*.dat
add fuzz_aerodyn cases/nrel5mw/aero/AeroDyn.dat tests/data/openfast/aero/*/AeroDyn.dat
add fuzz_ad_blade cases/nrel5mw/5MW_Baseline/*_AeroDyn_blade.dat
add fuzz_airfoil cases/nrel5mw/5MW_Baseline/Airfoils/*.dat cases/aero_rotor/airfoils/*.dat
add fuzz_inflowwind cases/nrel5mw/aero/InflowWind.dat tests/data/openfast/aero/*/InflowWind*.dat
add fuzz_servodyn_aero cases/nrel5mw/aero/ServoDyn.dat cases/nrel5mw/*_ServoDyn.dat tests/data/openfast/aero/*/ServoDyn.dat
add fuzz_read_aerodyn14 tests/data/openfast/decks/certtest/*/*_AD.ipt tests/data/openfast/decks/certtest/*/*_AeroDyn.dat \
  tests/data/openfast/decks/certtest/WP_Baseline/WP_Baseline_AeroDyn_Dynin.dat
add fuzz_read_airfoil14 tests/data/openfast/decks/certtest/*/AeroData/*.dat
add fuzz_read_wamit_ss cases/*/5MW_Baseline/HydroData/*.ss
add fuzz_read_map cases/*/5MW_Baseline/*_MAP.dat
add fuzz_read_moordyn cases/*/5MW_Baseline/*_MoorDyn.dat
add fuzz_read_hydrodyn cases/*/5MW_Baseline/*_HydroDyn.dat tests/data/openfast/decks/certtest/5MW_Baseline/*_HydroDyn.dat \
  tests/data/openfast/v4_seastate/HydroDyn.dat
add fuzz_read_seastate tests/data/openfast/v4_seastate/SeaState.dat
add fuzz_read_hydrodyn cases/*/5MW_Baseline/*_HydroDyn.dat tests/data/openfast/decks/certtest/5MW_Baseline/*_HydroDyn.dat
add fuzz_read_discon cases/nrel5mw/rosco/DISCON.IN
add fuzz_lin tests/data/openfast-lin/*/*.lin
add fuzz_read_beamdyn cases/nrel5mw_beamdyn/5MW_Baseline/*_BeamDyn_Blade.dat
add fuzz_subdyn cases/oc3_monopile/5MW_Baseline/*_SubDyn.dat tests/data/subdyn/*.dat
add fuzz_schedule cases/nrel5mw/NREL5MW_Oper.csv tests/mpi/*.csv fuzz/seeds/schedule/*
add fuzz_compare cases/*/table9_1.csv cases/*/reference.csv fuzz/seeds/compare/*
add fuzz_tracking fuzz/seeds/tracking/*
add fuzz_rotor_performance tests/data/rosco/Cp_Ct_Cq.NREL5MW.txt
# The FuzzedDataProvider harnesses decode any bytes: the small cases give their YAML-case path text to start from.
for h in fuzz_cli fuzz_study fuzz_simulate; do add $h cases/landbased_2dof/*.yaml cases/flex_4dof/*.yaml cases/tower_topmass/tower_topmass.yaml; done
add fuzz_writers cases/*/reference.csv
for h in aerodyn ad_blade airfoil inflowwind; do cp -r "$out/fuzz_$h" "$out/fuzz_read_$h"; done
cp -r "$out/fuzz_servodyn_aero" "$out/fuzz_read_servodyn"
for h in case_yaml fst elastodyn ed_tower ed_blade; do cp -r "$out/fuzz_$h" "$out/fuzz_read_$h"; done
for d in "$out"/*; do echo "$(basename "$d"): $(ls "$d" | wc -l) seeds"; done
