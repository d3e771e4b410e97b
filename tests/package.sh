#!/bin/sh
# The installed package as an outside project uses it: `cmake --install`
# of this build into a scratch prefix, then examples/embed and
# examples/sim-loop configured with find_package(mbc) against that prefix,
# built, and run to their expected output; the installed mbc links `mbc
# build` executables with the installed libraries, not the build tree's.
#   package.sh MBC BUILD_DIR SOURCE_DIR [SANITIZERS]
build=$(realpath "$2")
source=$(realpath "$3")
. "$(dirname "$0")/script_env.sh"
sanitize=${4:-}
prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" >install.log 2>&1 ||
  { cat install.log; fail "cmake --install"; }
[ -f "$prefix/lib/cmake/mbc/mbcConfig.cmake" ] || fail "no package config installed"
[ -f "$prefix/include/mbc/runtime.h" ] || fail "no runtime.h installed"

# A runtime built with sanitizers links only with their libraries.
flags=""
[ -n "$sanitize" ] && flags="-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=$sanitize"
for example in embed sim-loop; do
  out=$work/$example
  cmake -S "$source/examples/$example" -B "$out" -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_BUILD_TYPE=Release $flags >"$out.log" 2>&1 &&
    cmake --build "$out" >>"$out.log" 2>&1 ||
    { cat "$out.log"; fail "building examples/$example against the package"; }
  grep -rq --include=build.make "$prefix/bin/mbc compile" "$out" ||
    fail "examples/$example did not compile with the installed mbc"
done
"$work/embed/embed_example" | diff -u "$source/examples/embed/expected_output.txt" - ||
  fail "embed_example built against the package"
"$work/sim-loop/sim_loop" 2000 | grep -v '^throughput:' |
  diff -u "$source/examples/sim-loop/expected_output.txt" - ||
  fail "sim_loop built against the package"

printf '%%\nO1\n#100 = 7\nG01 X#100 F100\nM30\n%%\n' >p.nc
"$prefix/bin/mbc" build p.nc -o p -v 2>link.txt || { cat link.txt; fail "installed mbc build"; }
grep -q "$prefix/lib/libmbc_runtime.a" link.txt ||
  { cat link.txt; fail "installed mbc build did not link the installed runtime"; }
./p --toolpath - 2>/dev/null | grep -q '"x":7' || fail "the executable of the installed mbc"
echo "package: install, find_package(mbc), mbc_add_macro_library and mbc build work"
