#!/bin/bash
# The proof of docs/architecture.md's recipe for a new set of instructions:
# in a copy of the working tree, a set "sse41" (SSE4.1, over the SSE2
# lanes of base/lanes.h) is added by its enum entry and its line in
# RT_SIMD_BUILT_SETS (src/base/simd.h), its row in the chooser's table
# (src/base/simd.c) and its flags in the Makefile, and nothing else: no
# module names it.  The copy must build, choose it under WHITTED_ISA=sse41
# (--stats names it for the kernels, the walk and the packets), and render
# every scene of scenes/ and a 100k-triangle one byte for byte as this
# tree's default build does.  Only on x86-64, where the Makefile compiles
# the wide sets.
SUITE=newisa
. "$(dirname "$0")/lib.sh"
C=$T/tree
JOBS=${JOBS:-2}

case "$(${CC:-cc} -dumpmachine)" in
x86_64* | amd64*) ;;
*)
	skip "a new set" "not an x86-64 compiler: the build has the baseline alone"
	finish
	;;
esac
if ! grep -qw sse4_1 /proc/cpuinfo 2>/dev/null; then
	skip "a new set" "SSE4.1 not on this CPU"
	finish
fi

# The copy: the working tree as it is, with build/'s objects (make then
# rebuilds what includes base/simd.h and the new set's kernels).
mkdir -p "$C"
tar -C "$ROOT" --exclude=./.git --exclude=./build --exclude=./out --exclude='*.o' --exclude='*.d' \
	-cf - . | tar -C "$C" -xf -
if [ -d "$ROOT/build/src" ]; then
	tar -C "$ROOT" --exclude=./build/portable --exclude=./build/fuzz --exclude=./build/san \
		--exclude=./build/windows --exclude=./build/wasm --exclude=./build/web \
		--exclude=./build/bench-out -cf - build | tar -C "$C" -xf -
fi
cp -r "$C" "$T/orig"

# The recipe, file by file.
python3 - "$C" <<'PY'
import sys
root = sys.argv[1]
def edit(path, old, new):
    p = root + "/" + path
    s = open(p).read()
    if old not in s:
        sys.exit("newisa: %s: the recipe's anchor is gone: %r" % (path, old))
    open(p, "w").write(s.replace(old, new, 1))
edit("src/base/simd.h", "\tRT_SIMD_AVX2,\n", "\tRT_SIMD_SSE41,\n\tRT_SIMD_AVX2,\n")
edit("src/base/simd.h", "X(RT_SIMD_BASE, base, a, b) X(RT_SIMD_AVX2, avx2, a, b)",
     "X(RT_SIMD_BASE, base, a, b) X(RT_SIMD_SSE41, sse41, a, b) X(RT_SIMD_AVX2, avx2, a, b)")
edit("src/base/simd.c", "static int simd_cpu_avx2(void)",
     "static int simd_cpu_sse41(void)\n{\n\treturn SIMD_CPU(\"sse4.1\");\n}\n\nstatic int simd_cpu_avx2(void)")
edit("src/base/simd.c", "\t[RT_SIMD_AVX2] = {", "\t[RT_SIMD_SSE41] = { \"sse41\", simd_cpu_sse41 },\n\t[RT_SIMD_AVX2] = {")
edit("Makefile", "SIMD_SETS := base avx2 avx512", "SIMD_SETS := base sse41 avx2 avx512")
edit("Makefile", "SIMD_FLAGS_avx2 :=", "SIMD_FLAGS_sse41 := -msse4.1\nSIMD_FLAGS_avx2 :=")
PY
check "the recipe applies" [ $? -eq 0 ]
changed=$(diff -rq "$T/orig" "$C" | grep -v '/build/' | sed 's/^Files \([^ ]*\) and .*/\1/' | sed "s|^$T/orig/||" | sort | tr '\n' ' ')
check "the recipe changes 3 files: $changed" [ "$changed" = "Makefile src/base/simd.c src/base/simd.h " ]
lines=$(diff -r "$T/orig" "$C" -x build | grep -c '^[<>]')
check "the recipe changes 12 lines ($lines)" [ "$lines" -eq 12 ]
rm -rf "$T/orig"

if ! make -C "$C" --no-print-directory -j"$JOBS" build/whitted >"$T/all.log" 2>&1; then
	bad "make in the copy" "$(grep -m 5 -E 'error|Error' "$T/all.log")"
	finish
fi
check "the copy compiled the set's kernels" [ -f "$C/build/src/render/render_kernels_sse41.o" \
	-a -f "$C/build/src/accel/accel_kernels_sse41.o" -a -f "$C/build/src/shapes/solve_kernels_sse41.o" ]

NW=$C/build/whitted
"$ROOT/build/gen_scene" --layout surface 100000 >"$T/gen.txt" 2>/dev/null ||
	bad "gen_scene" "no 100k scene"
WHITTED_ISA=sse41 "$NW" --stats -q -s 32 -o "$T/s.ppm" "$T/gen.txt" 2>"$T/stats"
check "--stats names the new set's walk, packets and kernels" \
	grep -qF '(6.3 MiB, sse41 walk, sse41 packets, a ray a lane; sse41 kernels)' "$T/stats"
WHITTED_ISA=sse41 "$NW" --stats -q -s 32 -o "$T/s.ppm" "$ROOT/scenes/scene.txt" 2>"$T/stats"
check "a small scene's packets in the new set" grep -qF 'sse2 walk, sse41 packets, a ray a lane; sse41 kernels' "$T/stats"

# Every image the same bytes as this tree's default build's.
for f in "$ROOT"/scenes/*.txt "$T/gen.txt"; do
	for opt in "-s 61" "-s 96 --samples 2"; do
		"$W" -q $opt -o "$T/a.ppm" "$f" 2>/dev/null
		rc_a=$?
		WHITTED_ISA=sse41 "$NW" -q $opt -o "$T/b.ppm" "$f" 2>/dev/null
		rc_b=$?
		if [ "$rc_a" -ne 0 ] || [ "$rc_b" -ne 0 ]; then
			bad "$(basename "$f") $opt" "exit $rc_a and $rc_b"
		elif cmp -s "$T/a.ppm" "$T/b.ppm"; then
			ok
		else
			bad "$(basename "$f") $opt" "the new set's image differs"
		fi
	done
done
finish
