#!/usr/bin/env bash
# The runtime's rooms (docs/runtime.md) hold: every file of runtime/src is
# in a room, includes there name a file and never a path, and a room cannot
# include a header of a room above it. The last is shown on the build's own
# include paths: output/ reaches its flat_gcode.h and core's context.h, but
# not machine's motion.h.
#   tests/runtime_rooms.sh CXX OUTPUT_INCLUDE_DIRS ALL_ROOM_DIRS
# (each list separated by ';', as CMake gives it)
set -u
cxx=$1
IFS=';' read -r -a output_dirs <<<"$2"
IFS=';' read -r -a room_dirs <<<"$3"
src=$(cd "$(dirname "$0")/../runtime/src" && pwd)
status=0

for path in "$src"/* "$src"/*/*; do
  [ -d "$path" ] && [ "${path%/*}" = "$src" ] && continue
  known=0
  for dir in "${room_dirs[@]}"; do
    [ "${path%/*}" = "$dir" ] && known=1
  done
  if [ $known = 0 ]; then
    echo "runtime/src/${path#"$src"/}: not in a room of runtime/CMakeLists.txt"
    status=1
  fi
done

if grep -rn '#include "[^"]*/' "$src"; then
  echo "runtime/src: an include names a path; name the file (docs/runtime.md)"
  status=1
fi

includes=()
for dir in "${output_dirs[@]}"; do
  includes+=("-I$dir")
done
check() { # CODE HEADER: does `#include "HEADER"` compile in output/?
  echo "#include \"$2\"" | "$cxx" -std=c++20 -fsyntax-only -x c++ - \
    "${includes[@]}" 2>/dev/null
}
for header in flat_gcode.h context.h; do
  if ! check ok "$header"; then
    echo "output/ cannot include $header, which it may"
    status=1
  fi
done
if check no motion.h; then
  echo "output/ can include machine/motion.h: the rooms are not enforced"
  status=1
fi
exit $status
