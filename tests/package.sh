#!/bin/sh
# The installed package as an outside project uses it: `cmake --install`
# of this build into a scratch prefix, then examples/embed and
# examples/sim-loop configured with find_package(mbc) against that prefix,
# built, and run to their expected output; the installed mbc links `mbc
# build` executables with the installed libraries, not the build tree's;
# C programs link the shared runtime through pkg-config; the Python package
# runs from the prefix.
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
[ -f "$prefix/share/man/man1/mbc-run.1" ] || fail "no man page installed"
[ -f "$prefix/share/bash-completion/completions/mbc" ] || fail "no bash completion installed"

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

# A C project (no C++ at all) uses mbc_add_macro_library too.
cmake -S "$source/tests/c_project" -B c-build -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_BUILD_TYPE=Release $flags >c-project.log 2>&1 &&
  cmake --build c-build >>c-project.log 2>&1 ||
  { cat c-project.log; fail "tests/c_project, a C project with mbc_add_macro_library"; }
[ "$(./c-build/sim)" = 7 ] || fail "the C project's program"

printf '%%\nO1\n#100 = 7\nG01 X#100 F100\nM30\n%%\n' >p.nc
"$prefix/bin/mbc" build p.nc -o p -v 2>link.txt || { cat link.txt; fail "installed mbc build"; }
grep -q "$prefix/lib/libmbc_runtime.a" link.txt ||
  { cat link.txt; fail "installed mbc build did not link the installed runtime"; }
./p --toolpath - 2>/dev/null | grep -q '"x":7' || fail "the executable of the installed mbc"
# C users link through pkg-config with nothing written by hand: the shared
# runtime brings fmt and the C++ library, and exports the C ABI alone.
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
printf '#include <mbc/version.h>\nMBC_VERSION_STRING\n' >version.c
version=$(cc -E -P -I"$prefix/include" version.c | tr -d '" ')
[ "$(pkg-config --modversion mbc)" = "$version" ] ||
  fail "pkg-config --modversion mbc is not the installed version.h's ($version)"
sanitize_flag=""
[ -n "$sanitize" ] && sanitize_flag="-fsanitize=$sanitize"
# The C project's program, its cycle compiled by hand.
"$prefix/bin/mbc" compile -c "$source/tests/c_project/cycle.nc" -o p.o \
  --header cycle.h || fail "installed mbc compile"
# shellcheck disable=SC2046 # pkg-config's words are separate arguments
cc -std=c99 -Wall -Wextra -Wpedantic -Werror $sanitize_flag $(pkg-config --cflags mbc) \
  -I. "$source/tests/c_project/main.c" p.o $(pkg-config --libs mbc) -o call >cc.log 2>&1 ||
  { cat cc.log; fail "a C program with a compiled cycle, linked by pkg-config"; }
[ "$(LD_LIBRARY_PATH="$prefix/lib" ./call)" = 7 ] || fail "the pkg-config-linked program"
# shellcheck disable=SC2046
cc -std=c99 -Wall -Wextra -Wpedantic -Werror $sanitize_flag $(pkg-config --cflags mbc) \
  "$source/tests/c/runtime_from_c.c" $(pkg-config --libs mbc) -o from_c >cc.log 2>&1 ||
  { cat cc.log; fail "tests/c/runtime_from_c.c against the installed runtime.h alone"; }
LD_LIBRARY_PATH="$prefix/lib" ./from_c || fail "runtime_from_c linked by pkg-config"
readelf -d call | grep -q 'NEEDED.*libmbc_runtime\.so\.' ||
  fail "the program does not load the shared runtime"
exported=$(nm -D --defined-only "$prefix/lib/libmbc_runtime.so" | awk '{print $3}' |
  grep -v '^mbrt_' || true)
[ -z "$exported" ] || fail "the shared runtime exports more than its C ABI: $exported"

# The installed Python package (not built under sanitizers): it imports
# from the prefix and compiles with the installed code generator, found
# from the extension's own place.
pydir=$(cd "$prefix" && ls -d lib/python3*/dist-packages 2>/dev/null | head -n 1)
if [ -n "$pydir" ]; then
  MBC_CACHE_DIR=$work/pycache LD_DEBUG=files PYTHONPATH="$prefix/$pydir" \
    /usr/bin/python3 -c 'import mbc; print(mbc.compile("%\nO1\n#100=7\nG01X#100F100\nM30\n%\n")().motions["x"][0])' \
    >py.txt 2>ld.txt || { cat ld.txt; fail "the installed Python package"; }
  [ "$(cat py.txt)" = 7.0 ] || fail "the installed Python package ran wrong: $(cat py.txt)"
  grep -q "file=$prefix/lib/mbc/libmbc_codegen.so" ld.txt ||
    fail "the installed Python package did not load the installed code generator"
fi

echo "package: install, find_package(mbc), mbc_add_macro_library, mbc build and pkg-config work"
