# SPDX-License-Identifier: Apache-2.0
# The Snakemake workflow (workflow/Snakefile) on the structures shipped in
# the repository, in chunks of 4: its tables must be byte-identical to one
# `alphapocket batch` run over the same structures.
#   bash snakemake.sh ALPHAPOCKET REPO_ROOT CASE
#   local   snakemake --cores 2 (a folder as input); a second run does nothing;
#           one after a chunk job died redoes that chunk, which resumes
#   plan    200,000 listed structures plan 200 jobs; duplicate ids stop it
#   slurm   the same through a real single-node Slurm cluster started here
#           (tests/workflow/slurm.sh), the profile workflow/profiles/slurm,
#           a list file as input and $USER unset
# Needs snakemake, sqlite3, and for slurm: slurm-wlm, munge, root.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../cli/lib.sh"
source "$(dirname "${BASH_SOURCE[0]}")/slurm.sh"
trap 'slurm_stop; chmod -R u+rwx "$tmp"; rm -rf "$tmp"' EXIT
exe=$(realpath "$exe")  # the workflow runs in $tmp

for tool in snakemake sqlite3; do
  command -v $tool >/dev/null || fail "$tool not found (Debian: apt-get install $tool)"
done

# 19 structures with distinct ids (1UYD and truncated come twice in
# tests/data): 12 real ones (2 AlphaFold models) and 7 bad ones, so that the
# last two chunks fail whole.
cd "$tmp"
mkdir -p in/bad
for f in "$data"/1UYD.pdb "$data"/1d3z_models_1_2.pdb.gz "$data"/1fbl.pdb "$data"/1fkgA.pdb "$data"/1grm_single.pdb \
         "$data"/1pfe.cif.gz "$data"/1ytjA.pdb "$data"/3stdA.pdb "$data"/5i55.cif "$data"/AF-*.gz "$pdb" "$data"/bad/*; do
  ln -s "$f" in/"$(basename "$f")"
done
mv in/truncated.cif in/bad/truncated_cif.cif
rm in/truncated.pdb  # the reader's cut PDB case: its id would repeat truncated.pdb.gz's
mv in/{corrupt,empty,not_structure,short_line,three_atoms}.* in/truncated.pdb.gz in/bad/
find in -name '*.*' -type l | sort >structures.txt
[[ $(wc -l <structures.txt) -eq 19 ]] || fail "expected 19 structures, have $(wc -l <structures.txt)"

tables=(structures.csv sites.csv tunnels.csv failures.tsv)

# The reference: one batch run (exit 3: some structures failed).
reference() {
  run -q batch in -o reference -j 2
  [[ $rc -eq 3 ]] || fail "batch exit code $rc, expected 3"
  [[ $(tail -n +2 reference/failures.tsv | wc -l) -eq 7 ]] || fail "reference: expected 7 failures"
  [[ $(tail -n +2 reference/sites.csv | wc -l) -gt 12 ]] || fail "reference: too few sites"
}

same_tables() {  # DIR
  local t
  for t in "${tables[@]}"; do
    cmp -s "reference/$t" "$1/$t" || fail "$1/$t differs from one batch run's: $(diff "reference/$t" "$1/$t" | head -n 5)"
  done
  [[ -s reference/alphapocket.sqlite && -s $1/alphapocket.sqlite ]] || fail "no alphapocket.sqlite in reference/ or $1"
  [[ $(sqlite3 reference/alphapocket.sqlite .dump) == $(sqlite3 "$1/alphapocket.sqlite" .dump) ]] ||
    fail "$1/alphapocket.sqlite differs from one batch run's"
}

workflow() {  # INPUT-CONFIG SNAKEMAKE-ARGS...: the workflow into screen/, its log in $tmp/err
  local input=$1
  shift
  set +e
  env -u USER snakemake -s "$root/workflow/Snakefile" "$@" --config "$input" alphapocket="$exe" outdir=screen \
      chunk_size=4 threads=1 mem_mb=1000 runtime=10 >"$tmp/out" 2>"$tmp/err"
  rc=$?
  set -e
  [[ $rc -eq 0 ]] || fail "snakemake exit code $rc"
}

case $case_name in
local)
  reference
  workflow input=in --cores 2
  same_tables screen
  [[ $(ls screen/chunks | grep -c '^chunk_[0-9]*\.txt$') -eq 5 ]] || fail "expected 5 chunk lists"
  workflow input=in --cores 2
  grep -q "Nothing to be done" "$tmp/err" || fail "a second run did work again"
  # A run whose chunk 1 was killed mid-way (2 of its 4 records, no tables,
  # so no merge): the next run redoes that chunk alone, whose batch
  # resumes, and the merge.
  rm screen/chunks/1/structures.csv "${tables[@]/#/screen/}" screen/alphapocket.sqlite
  head -n 2 screen/chunks/1/records.jsonl >records && mv records screen/chunks/1/records.jsonl
  workflow input=in --cores 2
  grep -Eq '^chunk +1 ' "$tmp/err" || fail "the run did not redo exactly one chunk"
  grep -q '(2 done before)' screen/chunks/1.log || fail "chunk 1 did not resume: $(cat screen/chunks/1.log)"
  same_tables screen
  ;;
plan)
  # 200,000 listed structures (not there: a dry run reads none) plan 200
  # jobs of 1,000 (the default chunk size), not 200,000.
  seq -f 'afdb/AF-%07.0f-F1-model_v4.cif.gz' 0 199999 >big.txt
  run_snakemake() { set +e; env -u USER snakemake -s "$root/workflow/Snakefile" "$@" >"$tmp/out" 2>"$tmp/err"; rc=$?; set -e; }
  run_snakemake -n -q --cores 2 --config list=big.txt outdir=screen alphapocket="$exe"
  [[ $rc -eq 0 ]] || fail "snakemake -n exit code $rc"
  cat "$tmp/out" "$tmp/err" | grep -Eq "^chunk +200 " || fail "expected 200 chunk jobs"
  [[ $(wc -l <screen/chunks/chunk_199.txt) -eq 1000 ]] || fail "the last chunk does not hold 1000 structures"
  [[ $(head -n 1 screen/chunks/chunk_0.txt) == afdb/AF-0000000-F1-model_v4.cif.gz ]] || fail "chunk 0 starts wrong"
  # Two inputs with one structure id: an error naming both, before any job.
  run_snakemake --cores 2 --config input="[in, $data/1UYD.cif]" outdir=dup alphapocket="$exe"
  [[ $rc -ne 0 ]] || fail "duplicate ids: snakemake exit code 0"
  grep -q "two inputs with the structure id '1UYD': .*1UYD.cif and in/1UYD.pdb" "$tmp/err" ||
    fail "duplicate ids: no error naming both"
  [[ ! -e dup/chunks/0 ]] || fail "duplicate ids: a job ran"
  ;;
slurm)
  [[ $(id -u) -eq 0 ]] || { echo "the Slurm test runs slurmd as root" >&2; exit 77; }
  reference
  start=$(date +%s.%N)
  slurm_start "$tmp/slurm" || fail "Slurm did not start: $(tail -n 20 "$tmp"/slurm/log/* 2>&1)"
  echo "slurm: node idle after $(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.1f", e - s }') s"
  start=$(date +%s.%N)
  workflow list=structures.txt --profile "$root/workflow/profiles/slurm"
  echo "slurm: workflow done after $(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.1f", e - s }') s"
  same_tables screen
  # Every job went through sbatch: 5 chunks and the merge, each one
  # completed in Slurm's own records and its log.
  mapfile -t ids < <(grep -o 'submitted with SLURM jobid [0-9]*' "$tmp/err" | grep -o '[0-9]*$')
  [[ ${#ids[@]} -eq 6 ]] || fail "expected 6 Slurm jobs, Snakemake submitted ${#ids[@]}"
  for id in "${ids[@]}"; do
    scontrol show job "$id" | grep -q 'JobState=COMPLETED' || fail "Slurm job $id: $(scontrol show job "$id")"
    grep -q "_job_complete: JobId=$id done" "$tmp/slurm/log/slurmctld.log" ||
      fail "Slurm job $id is not done in slurmctld's log"
  done
  ;;
*)
  fail "unknown case"
  ;;
esac
