#!/usr/bin/env bash
# Hostile-input campaign: every input file of the beam pipeline, truncated and byte-flipped, fed
# to the tool that reads it. Each run must end in exit 0, or exit 1/2 with exactly one line
# "<tool>: error: ..." / "<tool>: usage error: ..." on stderr; a signal (crash, sanitizer abort),
# a hang (over TIMEOUT s), another exit code or another stderr is a defect. Prints one line per
# (tool, input) with the counts, then the defects; exits 1 if there is any.
#   scripts/hostile_campaign.sh BIN_DIR [MUTATIONS_PER_FILE=30] [WORK_DIR=/tmp/xfem-campaign]
# With the ASan + UBSan tools (build-asan/tools) a sanitizer report is a crash too.
set -u
B=${1:?usage: hostile_campaign.sh BIN_DIR [MUTATIONS] [WORK_DIR]}
N=${2:-30}
W=${3:-/tmp/xfem-campaign}
TIMEOUT=${TIMEOUT:-120}
SRC=$(cd "$(dirname "$0")/.." && pwd)
PROBLEM=$SRC/pipelines/beam/problem.json
EXACT=$SRC/pipelines/verification/data/rigid_exact.json
rm -rf "$W"; mkdir -p "$W/good" "$W/bad"
G=$W/good
"$B/xfem-mesh" -q box --cells 2 3 8 --hi 0.03 0.06 0.2 -o "$G/beam.vtu" &&
  "$B/xfem-mesh" -q cut-rect --beam-cut -o "$G/cut.vtp" &&
  "$B/xfem-classify" -q "$G/beam.vtu" --cut "$G/cut.vtp" -o "$G/classified.vtu" &&
  "$B/xfem-enrich" -q "$G/classified.vtu" -o "$G/enriched.vtu" &&
  "$B/xfem-assemble" -q "$G/enriched.vtu" --cut "$G/cut.vtp" --problem "$PROBLEM" --format mtx -o "$G/system" &&
  "$B/xfem-solve" -q "$G/system" -o "$G/u.mtx" &&
  cp "$PROBLEM" "$G/problem.json" && cp "$EXACT" "$G/exact.json" || { echo "campaign: the good pipeline failed" >&2; exit 1; }

# mutate IN OUT K: the K-th mutation: truncation (K < 8, at K/8 of the size), else one to four
# bytes set to random values (seeded by K, reproducible).
mutate() {
  python3 - "$1" "$2" "$3" <<'EOF'
import random, sys
data = bytearray(open(sys.argv[1], 'rb').read()); k = int(sys.argv[3]); r = random.Random(k)
if k < 8:
    data = data[:len(data) * k // 8]
else:
    for _ in range(r.randint(1, 4)):
        i = r.randrange(len(data)); data[i] = r.choice([r.randrange(256), ord(r.choice('0123456789-+.eE \n"{}[],:'))])
open(sys.argv[2], 'wb').write(data)
EOF
}

defects=()
# attack TOOL FILE (in good/) COMMAND...: COMMAND reads $BAD (a mutated copy of FILE, same name) or
# $BADDIR (a copy of the system directory with FILE replaced).
attack() {
  local tool=$1 file=$2; shift 2
  local ok=0 refused=0 bad=0
  for k in $(seq 0 $((N - 1))); do
    local case=$W/bad/$tool-$(basename "$file")-$k
    rm -rf "$case"; mkdir -p "$case/out"
    if [[ $file == system/* ]]; then
      cp -r "$G/system" "$case/system"; mutate "$G/$file" "$case/$file" "$k"
    else
      mutate "$G/$file" "$case/$(basename "$file")" "$k"
    fi
    BAD=$case/$(basename "$file") BADDIR=$case/system OUT=$case/out \
      timeout -s KILL "$TIMEOUT" "$@" >"$case/stdout" 2>"$case/stderr"
    local rc=$?
    if [ $rc -eq 0 ]; then
      ok=$((ok + 1))
    elif { [ $rc -eq 1 ] || [ $rc -eq 2 ]; } && [ "$(wc -l <"$case/stderr")" -eq 1 ] &&
         grep -q "^$tool: \(usage \)\?error: " "$case/stderr"; then
      refused=$((refused + 1))
    else
      bad=$((bad + 1))
      defects+=("$tool $file #$k: exit $rc: $(head -c 300 "$case/stderr" | tr '\n' ' ')")
      continue
    fi
    rm -rf "$case"
  done
  printf '%-16s %-22s tried %3d  exit 0 %3d  refused %3d  defects %d\n' "$tool" "$file" "$N" "$ok" "$refused" "$bad"
}

export B G
attack xfem-classify beam.vtu sh -c '"$B/xfem-classify" -q "$BAD" --cut "$G/cut.vtp" -o "$OUT/c.vtu"'
attack xfem-classify cut.vtp sh -c '"$B/xfem-classify" -q "$G/beam.vtu" --cut "$BAD" -o "$OUT/c.vtu"'
attack xfem-enrich classified.vtu sh -c '"$B/xfem-enrich" -q "$BAD" -o "$OUT/e.vtu"'
attack xfem-assemble enriched.vtu sh -c '"$B/xfem-assemble" -q "$BAD" --cut "$G/cut.vtp" --problem "$G/problem.json" -o "$OUT/s"'
attack xfem-assemble problem.json sh -c '"$B/xfem-assemble" -q "$G/enriched.vtu" --cut "$G/cut.vtp" --problem "$BAD" -o "$OUT/s"'
for f in K.mtx f.mtx dirichlet.mtx coordinates.mtx system.json provenance.json; do
  [ -e "$G/system/$f" ] && attack xfem-solve "system/$f" sh -c '"$B/xfem-solve" -q "$BADDIR" -o "$OUT/u.mtx"'
done
attack xfem-visualize u.mtx sh -c '"$B/xfem-visualize" -q "$G/enriched.vtu" --cut "$G/cut.vtp" -s "$BAD" -p "$G/problem.json" -o "$OUT/d.vtu"'
attack xfem-visualize problem.json sh -c '"$B/xfem-visualize" -q "$G/enriched.vtu" --cut "$G/cut.vtp" -s "$G/u.mtx" -p "$BAD" -o "$OUT/d.vtu"'
attack xfem-rmserror u.mtx sh -c '"$B/xfem-rmserror" -q "$G/enriched.vtu" --cut "$G/cut.vtp" -s "$BAD" --exact "$G/exact.json"'
attack xfem-rmserror exact.json sh -c '"$B/xfem-rmserror" -q "$G/enriched.vtu" --cut "$G/cut.vtp" -s "$G/u.mtx" --exact "$BAD"'
attack xfem-rmserror enriched.vtu sh -c '"$B/xfem-rmserror" -q "$BAD" --cut "$G/cut.vtp" -s "$G/u.mtx" --exact "$G/exact.json"'

if [ ${#defects[@]} -gt 0 ]; then
  echo "defects (inputs kept in $W/bad):"
  printf '  %s\n' "${defects[@]}"
  exit 1
fi
echo "no defects"
