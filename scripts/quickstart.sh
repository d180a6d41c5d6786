#!/usr/bin/env bash
# README quick start, command 1: install what is missing, build (Release) and run the main job
# on the shipped Manchester benchmark case. Results go to out/manchester/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
./build/mhcontact run cases/manchester.json -o out/manchester
echo "results: out/manchester/cases.csv, out/manchester/ellipses.csv, out/manchester/geometry.csv, out/manchester/results.json"
