# Sourced by the scripts that read the report's A7 rigs (run from the repository root): a7_dir is
# $IK_A7_DIR, default ../shared/rigs/a7 (beside it, ../../paper holds the report's CSV files).
a7_dir="$(realpath -m "${IK_A7_DIR:-../shared/rigs/a7}")"

# Exits with one line on stderr when that folder is missing: "$1: ... folder is missing ...$2".
require_a7() {
  [ -d "$a7_dir" ] && return
  echo "$1: the report's A7 rigs folder is missing: $a7_dir; point IK_A7_DIR at the folder with its five rigs (ikea-lamp.json ... beast.json)${2:-}" >&2
  exit 1
}
