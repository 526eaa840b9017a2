#!/usr/bin/env bash
# What `whirl modes DECK` does with each public OpenFAST deck: docs/user/decks.md on stdout, a Markdown
# table with one row per primary file (runs, or the first line of the refusal), then the count.
#
#   bash scripts/deck-table.sh [DECKS_DIR] [WHIRL] > docs/user/decks.md
#
# DECKS_DIR defaults to ../shared/data/decks (the collection described in its README.md); WHIRL to
# build/whirl. The offshore certification tests Test19–25 (HydroDyn, SubDyn, moorings) are counted apart.
set -uo pipefail
cd "$(dirname "$0")/.."
decks=${1:-../shared/data/decks}
whirl=${2:-build/whirl}
[ -d "$decks" ] || { echo "deck-table.sh: no folder $decks" >&2; exit 2; }
[ -x "$whirl" ] || { echo "deck-table.sh: no executable $whirl (build it first)" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

cat <<'HEAD'
# Public OpenFAST decks and what whirl does with them

Each primary file of `../shared/data/decks` (FAST v8 certification tests, OpenFAST toolbox NREL 5MW,
IEA 3.4 MW reference turbine; its README names the sources) given to `whirl modes DECK` as shipped
and with `--set CompAero=0` (the structural model of the same deck, no AeroDyn read). The offshore
certification tests Test19–25 (HydroDyn, SubDyn, moorings: [Offshore](../theory/offshore.md)) are counted apart. "refused"
quotes the error line of the message; paths are relative to the decks folder. "notes:" lists the keys
whirl noted: the time-domain options of a simulation deck it linearizes as their steady counterpart
(dynamic BEMT, unsteady airfoils, tower influence, wind files) and a controller it does not run
([Aerodynamics](../theory/aerodynamics.md)).
Regenerate with `bash scripts/deck-table.sh > docs/user/decks.md` (after building `build/whirl`).
The slow CTest suite `EveryDeckSlow` (`tests/cli/test_cli_every_deck.cpp`, on copies of these decks in
`tests/data/openfast/decks`) runs each of them with `whirl modes --rpm 0` and `whirl campbell` from 0 to
rated rotor speed, as shipped and structure only, and fails on a refusal it does not list with its
reason below, on a crash or on an operating point that does not converge. The AWT-27 decks (Test01–05)
cannot be parked with their teeter free (the rotor's weight acts 0.38 m off the teeter pin, the deck's
teeter spring is 1 N m/rad: [Two-bladed and teetered rotors](openfast.md#two-bladed-and-teetered-rotors)); the table runs each deck at its
own RotSpeed, so Test01, 03 and 04 (53.3 rpm) run, and of Test02 and 05 (0 rpm) only Test02 with its
aerodynamics (12 m/s) finds a parked equilibrium; the suite runs their Campbell sweeps from half the
rated speed (Test03 and 05 in still air, where the teeter's equilibrium at half the rated speed lies on a
jump of one element's loads: [Aerodynamics](../theory/aerodynamics.md)). In AOC Test08 (a fixed yaw error) and UAE VI Test09 (30 deg yaw, 11 m/s) the in-plane wind
of the yaw exceeds the rotational speed at the blade root at some azimuths, and BEM has no valid inflow
angle there: those elements take the geometric inflow angle without induction, as AeroDyn does in its
simulation and its linearization (`BEMT_UnCoupledSolve`), and whirl says how many in one note. The decks with AeroDyn v14
(`CompAero = 1`: Test01, 04, 06, 09, 11, 16, 17) run through its conversion to AeroDyn v15's elements
and BEMT ([Aerodynamics](../theory/aerodynamics.md)); SWRT Test16 and 17 interpolate their airfoil tables on the Reynolds
number (`RENUM`), as AeroDyn v15's `AFTabMod = 2` does in log Re.
The deck with BeamDyn blades (`CompElast = 2`: Test26) runs with each blade a finite-element body of
6 × 6 sections reduced to its fixed-root modes ([FE blades](../theory/fe-blades.md)); so do the IEA 3.4's BeamDyn
variant and an aeroelastic NREL 5MW with BeamDyn blades, kept in `cases/iea34_beamdyn` and
`cases/nrel5mw_beamdyn`: 2 + 1 BeamDyn decks in all.

HEAD
echo "| deck | \`whirl modes DECK\` | \`whirl modes DECK --set CompAero=0\` (structure only) |"
echo "|---|---|---|"
# One cell: "runs (N modes)" or "refused: <first line of the message>".
cell() {
  if timeout 600 "$whirl" modes "$@" > "$tmp/out" 2> "$tmp/err"; then
    # The keys of the notes (time-domain options linearized as their steady counterpart, HydroDyn
    # inputs left out, a controller whirl does not run), e.g. "; notes: WakeMod, AFAeroMod".
    local keys
    keys=$(sed -n 's/^whirl: note: [^:]*:[0-9]*: \([A-Za-z_0-9()]*\): .*/\1/p' "$tmp/err" | paste -sd, - | sed 's/,/, /g')
    echo "runs ($(($(grep -c . "$tmp/out") - 1)) modes${keys:+; notes: $keys})"
    return 0
  fi
  local code=$?
  [ "$code" -eq 124 ] && { echo "timed out after 600 s"; return 1; }
  # Paths under DECKS_DIR shortened; table pipes escaped.
  echo "refused: $(grep -m 1 '^whirl: error: ' "$tmp/err" | sed -e "s|$decks/||g" -e 's/^whirl: error: //' -e 's/|/\\|/g')"
  return 1
}
runs=0 structural=0 total=0 off_runs=0 off_structural=0 off_total=0
while IFS= read -r fst; do
  rel=${fst#"$decks"/}
  offshore=0
  case "$rel" in certtest/Test19* | certtest/Test2[0-5]*) offshore=1 ;; esac
  a=$(cell "$fst") && a_ok=1 || a_ok=0
  b=$(cell "$fst" --set CompAero=0) && b_ok=1 || b_ok=0
  if [ $offshore -eq 1 ]; then
    off_total=$((off_total + 1)) off_runs=$((off_runs + a_ok)) off_structural=$((off_structural + b_ok))
  else
    total=$((total + 1)) runs=$((runs + a_ok)) structural=$((structural + b_ok))
  fi
  echo "| $rel | $a | $b |"
done < <(find "$decks" -name '*.fst' | LC_ALL=C sort)
echo
echo "$runs of $total decks run as shipped; $structural of $total run with \`--set CompAero=0\`."
echo "Offshore (Test19–25 and their \`_withIce\` variants): $off_runs of $off_total run as shipped; $off_structural of $off_total with \`--set CompAero=0\`."
