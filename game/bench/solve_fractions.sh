#!/bin/bash
# Measures every level's solve fraction with `rube solve` at the budget levels/index.toml gives it
# (solve_budget, seed 1) and writes it into the index as solve_fraction; prints level, budget,
# solutions, fraction and seconds. The level tests (solve_tests) check the index against the same
# measurement, so run this after changing a level or the search.
#   game/bench/solve_fractions.sh build/rube [levels/index.toml]
set -euo pipefail
rube=${1:?usage: solve_fractions.sh RUBE [INDEX]}
index=${2:-levels/index.toml}
folder=$(dirname "$index")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# The [[level]] tables in order: file and solve_budget.
awk -F'"' '/^file *=/ {file=$2} /^solve_budget *=/ {split($0, a, "= *"); print file, a[2]}' "$index" > "$tmp/levels"
cp "$index" "$tmp/index"
printf '%-16s %7s %9s %9s %8s\n' level budget solutions fraction seconds
while read -r file budget; do
  start=$(date +%s.%N)
  status=0
  "$rube" solve "$folder/$file" --budget "$budget" --json "$tmp/result.json" > /dev/null || status=$?
  [ "$status" -le 1 ] || exit "$status"
  fraction=$(sed -n 's/^  "solve_fraction": \([0-9.]*\),$/\1/p' "$tmp/result.json")
  solved=$(sed -n 's/^  "solved": \([0-9]*\),$/\1/p' "$tmp/result.json")
  printf '%-16s %7s %9s %9s %8.1f\n' "${file%.toml}" "$budget" "$solved" "$fraction" "$(echo "$(date +%s.%N) - $start" | bc)"
  # Rewrite this level's solve_fraction line (the one after its file line).
  awk -v file="$file" -v fraction="$fraction" -F'"' '
    /^file *=/ {mine = ($2 == file)}
    mine && /^solve_fraction *=/ {print "solve_fraction = " fraction; next}
    {print}' "$tmp/index" > "$tmp/index.new"
  mv "$tmp/index.new" "$tmp/index"
done < "$tmp/levels"
cp "$tmp/index" "$index"
