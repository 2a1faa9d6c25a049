# What scripts/adapt_study.sh and scripts/adapt_legs_study.sh share, sourced by both: making a
# map when it is missing, and adapting on every leg with each damage, one folder per run. A run
# already done (adapt.json) or refused (refused.txt, what `hexgait adapt` said) is kept, so an
# interrupted study resumes where it stopped.

# Every leg, in the creature's order.
ADAPT_LEGS=(right_front right_middle right_rear left_front left_middle left_rear)

# ensure_map HEXGAIT DIR EVALUATIONS SEED [repertoire flags...]: a repertoire in DIR unless one
# (or a link to one) is there.
ensure_map() {
  local hexgait=$1 dir=$2 evaluations=$3 seed=$4
  shift 4
  [ -f "$dir/repertoire.json" ] && return 0
  "$hexgait" repertoire "$@" --evaluations "$evaluations" --seed "$seed" --no-movie \
    --compare-ga 0 --quiet --out "$dir"
}

# adapt_each_leg HEXGAIT MAP PREFIX SUFFIX "KINDS" SEED [adapt flags...]: `hexgait adapt` on
# MAP for every leg with each damage kind in KINDS (e.g. "weak=0.2 locked"), into
# PREFIX_LEG_KIND SUFFIX (KIND without its '='). A run that exits for bad input (status 1: say,
# every elite falls on that creature) is recorded as refused; any other failure, an interrupt
# included, stops the study with its message, so it is run again on resuming.
adapt_each_leg() {
  local hexgait=$1 map=$2 prefix=$3 suffix=$4 kinds=$5 seed=$6
  shift 6
  local leg kind dir log
  for leg in "${ADAPT_LEGS[@]}"; do
    for kind in $kinds; do
      dir="${prefix}_${leg}_${kind/=/}$suffix"
      [ -e "$dir/adapt.json" ] || [ -e "$dir/refused.txt" ] && continue
      log="$(dirname "$prefix")/log_tmp"
      local status=0
      "$hexgait" adapt --repertoire "$map" --damage "$leg:$kind" --seed "$seed" --no-movie \
        --out "$dir" "$@" >"$log" 2>&1 || status=$?
      if [ "$status" -eq 1 ]; then  # bad input (docs/errors.md): this damage cannot be adapted to
        mkdir -p "$dir"
        mv "$log" "$dir/refused.txt"
      elif [ "$status" -ne 0 ]; then  # stopped or failed: not a result, the study stops
        cat "$log" >&2
        return "$status"
      fi
    done
  done
}
