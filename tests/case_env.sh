# Sourced by the case scripts with $case_path set: enters the case's folder
# (paths print relative to it), sets $name, a $work folder removed at exit,
# the fixed locale and date, and the lines of CASE.args in $args.
dir=${case_path%/*}
[ "$dir" = "$case_path" ] && dir=.
name=${case_path##*/}
name=${name%.nc}
cd "$dir" || exit 2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export LC_ALL=C SOURCE_DATE_EPOCH=1767225600
args=()
if [ -f "$name.args" ]; then
  mapfile -t args < <(grep -v '^[[:space:]]*$' "$name.args")
fi
