#!/bin/bash
# same-bits.sh: proves that two builds of meshpaint paint the same bits.
#
#   scripts/same-bits.sh OLD_BUILD_DIR NEW_BUILD_DIR [WORK_DIR]
#
# Runs every case of tests/same_bits/ (stroke scripts covering every tool,
# falloff, op, mode, pattern, brush space, stamps, spray, mirror, pressure,
# two-sided surfaces, a scene, coarse edit levels, a continued project, a
# picture with texture-space subsurface light, and undo/redo through the
# Python package; see tests/same_bits/README.md) with both builds, once with
# `--storage buffer` and once with `--storage image`, and compares every
# output file byte for byte with cmp: surface.vtp, LOD surfaces, model.obj,
# model.mtl, PNG maps, the project, the stroke table without its timings,
# label stats, the picture. One line per case and storage: `same` or
# `DIFFERS: files`. Exit status: 0 when every case ran and every file is the
# same, 1 when a file differs or a run failed, 2 for bad arguments or a
# broken build.
#
# Each build runs with its own libraries: LD_LIBRARY_PATH=BUILD/lib comes
# first (it wins over the RUNPATH that a copied build directory still points
# at the tree it was built in), PYTHONPATH=BUILD/python, and ldd is checked
# before anything runs. Both builds run with the same working directory
# layout and the same argument strings, so paths recorded in the outputs
# (a project's stroke history names its pattern files) agree.
#
# Outputs stay in WORK_DIR (default /tmp/meshpaint-same-bits): old/STORAGE/CASE
# and new/STORAGE/CASE, logs in logs/. Comparing a build with itself
# (OLD = NEW) checks that the cases are deterministic.
#
# Environment: SAME_BITS_STORAGES (default "buffer image"), SAME_BITS_CASES
# (names to run, default all; `continue` needs `paint_ops`), SAME_BITS_JOBS
# (1: run old and new one after the other; default 2: side by side),
# MESHPAINT_DEVICE (passed through, as the device both builds use).

set -u

usage() {
  echo "usage: $0 OLD_BUILD_DIR NEW_BUILD_DIR [WORK_DIR]" >&2
  exit 2
}
[ $# -ge 2 ] && [ $# -le 3 ] || usage

ROOT=$(cd "$(dirname "$0")/.." && pwd)
CASES=$ROOT/tests/same_bits
SCANS=$ROOT/data/scans
PYTHON=/usr/bin/python3
STORAGES=${SAME_BITS_STORAGES:-buffer image}
JOBS=${SAME_BITS_JOBS:-2}

OLD=$(cd "$1" 2>/dev/null && pwd) || { echo "same-bits: no build directory '$1'" >&2; exit 2; }
NEW=$(cd "$2" 2>/dev/null && pwd) || { echo "same-bits: no build directory '$2'" >&2; exit 2; }
WORK=${3:-/tmp/meshpaint-same-bits}

# name | inputs (scans, comma-separated; @CASE: that case's project; python:
# tests/same_bits/NAME.py) | save: --save the project, stats: `meshpaint stats
# --json` of it, shot: a screenshot (needs an X display, else xvfb-run) |
# more arguments (@FILE: a file of tests/same_bits)
CASE_TABLE='
paint_ops      | femur.off                 | save       | --lod 2 --model-level 2
continue       | @paint_ops                | save       |
smooth         | femur.off                 | save       |
smear          | femur.off                 | save       |
patterns       | femur.off                 | save       |
sampled        | femur.off                 | save       |
spray          | femur.off                 | save,stats |
modes          | lion-head.off             | save       |
sculpt         | lion-head.off             | save       | --lod 2
spaces         | lion-head.off             | save,stats |
stamps         | lion-head.off             | save       |
two_sided      | lion-head.off             | save,stats | --two-sided
mirror         | lion-head.off             | save       |
multires       | lion-head.off             | save       | --lod 1
label_wash_dip | bunny00.off               | save,stats | --labels @labels.json
pressure       | bunny00.off               | save       |
scene          | femur.off,lion-head.off   | -          | --two-sided
screenshot     | femur.off                 | save,shot  | --screenshot screenshot/shot.png --subsurface 30 --size 320x240 --camera 30,10,1.5
undo_redo      | python                    | -          |
'

for f in femur.off lion-head.off bunny00.off; do
  [ -f "$SCANS/$f" ] || { echo "same-bits: $SCANS/$f is missing: run scripts/fetch-scans.sh" >&2; exit 2; }
done

# inside BUILD PATH: PATH lies in BUILD, its lib/ or python/ (symbolic links followed or not).
inside() {
  local d p
  for d in "$1" "$(readlink -f "$1")" "$(readlink -f "$1/lib")" "$(readlink -f "$1/python")"; do
    for p in "$2" "$(readlink -f "$2")"; do
      case $p in "$d"/*) return 0 ;; esac
    done
  done
  return 1
}

# check_libs BUILD FILE: every library FILE needs that BUILD/lib holds must
# resolve to BUILD/lib (not to the tree a RUNPATH names), meshpaint's own
# libraries must come from inside BUILD, and none may be missing.
check_libs() {
  local build=$1 file=$2 line name path bad=0
  while IFS= read -r line; do
    case $line in
      *"not found"*) echo "same-bits: $file: $line" >&2; bad=1 ;;
      *" => "/*)
        name=${line%% => *}; name=${name#"${name%%[![:space:]]*}"}
        path=${line#* => }; path=${path%% (*}
        if [ -e "$build/lib/$name" ] && [ "$(readlink -f "$path")" != "$(readlink -f "$build/lib/$name")" ]; then
          echo "same-bits: $file loads $name from $path, not from $build/lib" >&2
          bad=1
        fi
        case $name in *[Mm]esh[Pp]aint*)
          inside "$build" "$path" || { echo "same-bits: $file loads $name from $path, outside $build" >&2; bad=1; } ;;
        esac ;;
    esac
  done < <(LD_LIBRARY_PATH="$build/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" ldd "$file" 2>&1)
  return $bad
}

check_build() {
  local build=$1 so
  [ -x "$build/bin/meshpaint" ] || { echo "same-bits: $build/bin/meshpaint is missing" >&2; return 1; }
  [ -f "$build/python/meshpaint/__init__.py" ] || { echo "same-bits: $build/python/meshpaint is missing" >&2; return 1; }
  check_libs "$build" "$build/bin/meshpaint" || return 1
  for so in "$build"/python/meshpaint/*.so; do
    check_libs "$build" "$so" || return 1
  done
  # The Python package as loaded: its shared objects must come from this build.
  local maps
  maps=$(cd / && PYTHONPATH="$build/python" LD_LIBRARY_PATH="$build/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" \
         "$PYTHON" -c 'import meshpaint; print(open("/proc/self/maps").read())' 2>&1) ||
    { echo "same-bits: cannot import meshpaint from $build/python: $maps" >&2; return 1; }
  local other
  other=$(printf '%s\n' "$maps" | awk '{print $6}' | grep -i meshpaint | sort -u |
          while read -r p; do inside "$build" "$p" || echo "$p"; done)
  [ -z "$other" ] || { echo "same-bits: Python with $build loads $other" >&2; return 1; }
}

check_build "$OLD" || exit 2
check_build "$NEW" || exit 2

if [ -e "$WORK" ] && [ ! -e "$WORK/.same-bits" ] && [ -n "$(ls -A "$WORK" 2>/dev/null)" ]; then
  echo "same-bits: $WORK exists and was not made by same-bits.sh; give an empty or new WORK_DIR" >&2
  exit 2
fi
mkdir -p "$WORK" || exit 2
touch "$WORK/.same-bits"
rm -rf "$WORK/old" "$WORK/new" "$WORK/logs"
mkdir -p "$WORK/logs"

trim() { local s=$1; s=${s#"${s%%[![:space:]]*}"}; printf '%s' "${s%"${s##*[![:space:]]}"}"; }

# run_case SIDE BUILD STORAGE NAME INPUTS FLAGS ARGS: one case with one build,
# in WORK/SIDE/STORAGE with relative output paths, so that both builds get
# the same argument strings. Always run in the background (its cd stays there).
run_case() {
  local side=$1 build=$2 storage=$3 name=$4 inputs=$5 flags=$6 args=$7
  local dir=$WORK/$side/$storage log=$WORK/logs/$side.$storage.$name.log
  local libs="$build/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  mkdir -p "$dir"
  cd "$dir" || return 1
  rm -rf "$name"
  if [ "$inputs" = python ]; then
    env PYTHONPATH="$build/python" LD_LIBRARY_PATH="$libs" MESHPAINT_STORAGE="$storage" \
      "$PYTHON" "$CASES/$name.py" "$name" >"$log" 2>&1
    return
  fi
  local -a cmd=("$build/bin/meshpaint" paint)
  local input arg
  IFS=, read -r -a list <<<"$inputs"
  for input in "${list[@]}"; do
    case $input in
      @*) cmd+=("${input#@}/project.meshpaint") ;;
      *) cmd+=("$SCANS/$input") ;;
    esac
  done
  cmd+=(--strokes "$CASES/$name.json" -o "$name" --storage "$storage")
  case ,$flags, in *,save,*) cmd+=(--save "$name/project.meshpaint") ;; esac
  for arg in $args; do
    case $arg in @*) cmd+=("$CASES/${arg#@}") ;; *) cmd+=("$arg") ;; esac
  done
  case ,$flags, in *,shot,*) [ -n "${DISPLAY:-}" ] || cmd=(xvfb-run -a "${cmd[@]}") ;; esac
  echo "+ ${cmd[*]}" >"$log"
  env -u MESHPAINT_STORAGE LD_LIBRARY_PATH="$libs" "${cmd[@]}" >"$log.out" 2>>"$log" || {
    local rc=$?; cat "$log.out" >>"$log"; rm -f "$log.out"; return $rc; }
  cat "$log.out" >>"$log"
  # The stroke table without its timings (column "ms"): dabs, dabs on the
  # surface, patches touched and notes are outputs too.
  awk '/^  -+$/ {t = 1; next} t && /^  [0-9]/ {s = $1 " " $2 " " $3 " " $4 " " $5;
       for (i = 7; i <= NF; i++) s = s " " $i; print s; next} t {t = 0}' "$log.out" >"$name/strokes.txt"
  rm -f "$log.out"
  case ,$flags, in
    *,stats,*)
      env -u MESHPAINT_STORAGE LD_LIBRARY_PATH="$libs" "$build/bin/meshpaint" stats "$name/project.meshpaint" \
        --json --storage "$storage" >"$name/stats.json" 2>>"$log" || return $? ;;
  esac
}

# compare NAME STORAGE: every file of both sides' case folders, byte for byte.
compare() {
  local name=$1 storage=$2 a=$WORK/old/$2/$1 b=$WORK/new/$2/$1 f differ="" n=0
  while IFS= read -r f; do
    n=$((n + 1))
    if [ ! -f "$a/$f" ]; then differ="$differ $f(only new)"
    elif [ ! -f "$b/$f" ]; then differ="$differ $f(only old)"
    elif ! cmp -s "$a/$f" "$b/$f"; then differ="$differ $f"
    fi
  done < <( { (cd "$a" && find . -type f); (cd "$b" && find . -type f); } | sed 's|^\./||' | sort -u)
  if [ "$n" -eq 0 ]; then
    echo "no output"
  elif [ -n "$differ" ]; then
    echo "DIFFERS:$differ"
  else
    echo "same ($n files)"
  fi
}

echo "old  $OLD"
echo "new  $NEW"
echo "work $WORK"
LD_LIBRARY_PATH="$OLD/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" "$OLD/bin/meshpaint" devices 2>&1 | sed 's/^/     /'

status=0
start=$(date +%s)
p=""
trap 'for q in $p; do pkill -TERM -P "$q"; kill "$q"; done 2>/dev/null; echo "same-bits: interrupted" >&2; exit 130' INT TERM
for storage in $STORAGES; do
  while IFS='|' read -r name inputs flags args; do
    name=$(trim "$name")
    [ -n "$name" ] || continue
    if [ -n "${SAME_BITS_CASES:-}" ]; then
      case " $SAME_BITS_CASES " in *" $name "*) ;; *) continue ;; esac
    fi
    inputs=$(trim "$inputs"); flags=$(trim "$flags"); args=$(trim "$args")
    if [ ",$flags," != "${flags/shot/}" ] && [ -z "${DISPLAY:-}" ] && ! command -v xvfb-run >/dev/null; then
      printf '%-7s %-15s %3ss  %s\n' "$storage" "$name" 0 "skipped (no X display and no xvfb-run)"
      continue
    fi
    t0=$(date +%s)
    # Side by side, except pictures: two xvfb-run -a starting at once may pick the same display.
    # (Runs go to the background and are waited for, so that a signal stops them at once.)
    run_case old "$OLD" "$storage" "$name" "$inputs" "$flags" "$args" </dev/null & p=$!
    if [ "$JOBS" -lt 2 ] || [ ",$flags," != "${flags/shot/}" ]; then
      wait $p; rc_old=$?
    fi
    run_case new "$NEW" "$storage" "$name" "$inputs" "$flags" "$args" </dev/null & p="$p $!"
    wait ${p##* }; rc_new=$?
    wait ${p%% *}; rc_old=$?
    p=""
    took=$(( $(date +%s) - t0 ))
    if [ $rc_old -ne 0 ] || [ $rc_new -ne 0 ]; then
      result="FAILED (exit old $rc_old, new $rc_new; see $WORK/logs/{old,new}.$storage.$name.log)"
      status=1
    else
      result=$(compare "$name" "$storage")
      case $result in same*) ;; *) status=1 ;; esac
      # A stroke with no dab on the surface paints nothing: a defect of the case.
      if [ -f "$WORK/old/$storage/$name/strokes.txt" ] &&
         ! awk '$4 == 0 {exit 1}' "$WORK/old/$storage/$name/strokes.txt"; then
        result="$result; WARNING: a stroke with no dab on the surface"
      fi
    fi
    printf '%-7s %-15s %3ss  %s\n' "$storage" "$name" "$took" "$result"
  done <<<"$CASE_TABLE"
done
echo "total $(( $(date +%s) - start )) s; $( [ $status -eq 0 ] && echo 'every case the same' || echo 'DIFFERENCES or FAILURES above')"
exit $status
