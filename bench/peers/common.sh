# Helpers sourced by the bench/peers scripts (bash): their arguments, two-seed renders, JSON fields, medians, wall clocks.

# run_arguments DEFAULT_OUT [BUILD] [THREADS] [OUT]: the scripts' shared arguments, as absolute paths: build
# (default build), threads (default 2), out (created), size ($SIZE, default 512), and the tools both use,
# trazo and imageError.
run_arguments() {
  local defaultOut=$1
  build=$(cd "${2:-build}" && pwd)
  threads=${3:-2}
  out=${4:-$defaultOut}
  mkdir -p "$out"
  out=$(cd "$out" && pwd)
  size=${SIZE:-512}
  trazo="$build/app/trazo"
  imageError="$build/bench/peers/image_error"
}

# two_seeds PREFIX TRAZO_ARGS...: `trazo TRAZO_ARGS` with seeds 1 and 2 into PREFIX_1/2.pfm and .json (its
# messages into PREFIX.log); prints the mean render_s, the two-seed variance mean((A − B)²)/2 and one image's
# relative deviation (image_error --variance).
two_seeds() {
  local prefix=$1 seed t stats
  shift
  for seed in 1 2; do
    "$trazo" "$@" --seed $seed --quiet -o "${prefix}_$seed.pfm" --stats "${prefix}_$seed.json" >/dev/null \
      2>"$prefix.log" || { echo "trazo failed, see $prefix.log" >&2; return 1; }
  done
  t=$(awk -v a="$(json_field "${prefix}_1.json" render_s)" -v b="$(json_field "${prefix}_2.json" render_s)" \
    'BEGIN { printf "%.4f", (a + b) / 2 }')
  stats=$("$imageError" --variance "${prefix}_1.pfm" "${prefix}_2.pfm")
  echo "$t $(field "$stats" variance) $(field "$stats" rel_sd)"
}

# json_field FILE KEY: the value of a flat "KEY": value line of the stats JSON trazo --stats writes.
json_field() {
  sed -n "s/^ *\"$2\": *\"\{0,1\}\([^\",]*\)\"\{0,1\},\{0,1\} *$/\1/p" "$1" | head -n 1
}

# median V1 V2 ...: the middle value (the lower middle of an even count).
median() {
  printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'
}

# now: seconds since the epoch with nanoseconds, for whole-process wall times.
now() { date +%s.%N; }

# elapsed START END: END - START in seconds.
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.4f", b - a }'; }

# field "rel_error 0.01 rmse ..." rel_error: the value after a name in image_error's output.
field() { awk -v k="$2" '{ for (i = 1; i < NF; ++i) if ($i == k) { print $(i + 1); exit } }' <<<"$1"; }
