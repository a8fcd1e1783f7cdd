#!/bin/bash
# Run-time plugins end to end (whitted/plugin.h, docs/plugins.md): every
# load error of every tool with its message and exit status 1 and no
# output written (a missing file, a file that is no shared object, a
# shared object without the entry points, another ABI version, a keyword
# of a built-in or of another plugin, a second plugin of the same name, an
# init that fails), also after a good plugin, and under valgrind;
# WHITTED_PLUGIN_PATH and --plugin overriding it; --list-shapes and its
# usage errors; the same image with
# 1, 2 and 7 threads and from merged tiles; tiles that record their
# plugins, and merge refusing tiles of another build of a plugin.
SUITE=plugintest
. "$(dirname "$0")/lib.sh"
P=$ROOT/build/plugins
S2P=$ROOT/build/scene2pov
VIEW=$ROOT/build/whitted-view
CC=${CC:-cc}
for so in quad cylinder torus; do
	[ -f "$P/$so.so" ] || { echo "$SUITE: $P/$so.so is missing (make plugins)"; echo "$SUITE: 0 passed, 1 failed, 0 skipped"; exit 1; }
done
cd "$T" || exit 1

# A plugin needs nothing of whitted's own: what each example leaves
# undefined is the C library's (versioned symbols) or the toolchain's weak
# hooks, never an rt_/parser_/pov_/mesh_ function.
for so in quad cylinder torus; do
	extra=$(nm -D --undefined-only "$P/$so.so" | awk '{ print $2 }' |
		grep -v -e '@GLIBC_' -e '^_ITM_' -e '^__gmon_start__$' | tr '\n' ' ')
	check "$so.so needs only the C library (not: $extra)" [ -z "$extra" ]
done

# The bad plugins of tests/plugins/, and files that are no plugin at all.
build() { "$CC" -std=c99 -Wall -Wextra -Werror -I"$ROOT/include" -fPIC -shared -o "$@"; }
build bad_abi.so "$ROOT/tests/plugins/bad_abi.c" &&
	build old_abi.so -DBAD_ABI=1 "$ROOT/tests/plugins/bad_abi.c" &&
	build old2_abi.so -DBAD_ABI=4 "$ROOT/tests/plugins/bad_abi.c" &&
	build no_entry.so "$ROOT/tests/plugins/no_entry.c" &&
	build init_fails.so "$ROOT/tests/plugins/init_fails.c" &&
	build clash_sphere.so -DCLASH_KEYWORD='"sphere"' "$ROOT/tests/plugins/clash.c" &&
	build clash_quad.so -DCLASH_KEYWORD='"quad"' "$ROOT/tests/plugins/clash.c"
check "the bad plugins build" [ $? -eq 0 ]
for i in $(seq 40); do echo "not an ELF file"; done >text.so
cp "$P/quad.so" quad-copy.so
mkdir -p dir && cp "$P/torus.so" dir/torus.so
cp "$ROOT/scenes/plugins/torus.txt" torus.txt

# expect_fail NAME PATTERN TOOL ARGS...: exit 1, PATTERN on stderr, and no
# out.* file left behind.
expect_fail() {
	local name=$1 pattern=$2
	shift 2
	rm -f out.png out.pov err
	"$@" >/dev/null 2>err
	local rc=$?
	if [ $rc -ne 1 ]; then
		bad "$name" "exit $rc, expected 1: $(head -c 300 err)"
	elif ! grep -q -- "$pattern" err; then
		bad "$name" "stderr lacks '$pattern': $(head -c 300 err)"
	elif ls out.* >/dev/null 2>&1; then
		bad "$name" "an output file was left behind: $(ls out.*)"
	else
		ok
	fi
}

for tool in whitted scene2pov whitted-view; do
	case $tool in
	whitted) run=("$W" -s 16 -o out.png) ;;
	scene2pov) run=("$S2P" -o out.pov) ;;
	whitted-view) [ -x "$VIEW" ] || { bad "$tool" "$VIEW is missing"; continue; }; run=("$VIEW") ;;
	esac
	expect_fail "$tool missing" "plugin nowhere.so: No such file or directory" \
		"${run[@]}" --plugin nowhere.so torus.txt
	expect_fail "$tool not ELF" "plugin text.so: not a plugin: .*invalid ELF header" \
		"${run[@]}" --plugin text.so torus.txt
	expect_fail "$tool no entry" "plugin no_entry.so: not a whitted plugin (it defines no whitted_plugin_abi" \
		"${run[@]}" --plugin no_entry.so torus.txt
	expect_fail "$tool abi" "plugin bad_abi.so: built for plugin ABI version 99, but this whitted supports version 5 only" \
		"${run[@]}" --plugin bad_abi.so torus.txt
	expect_fail "$tool older abi" "plugin old_abi.so: built for plugin ABI version 1, but this whitted supports version 5 only" \
		"${run[@]}" --plugin old_abi.so torus.txt
	expect_fail "$tool abi 4" "plugin old2_abi.so: built for plugin ABI version 4, but this whitted supports version 5 only" \
		"${run[@]}" --plugin old2_abi.so torus.txt
	expect_fail "$tool clash built-in" "plugin clash_sphere.so: shape keyword 'sphere' is already defined by whitted (built in)" \
		"${run[@]}" --plugin clash_sphere.so torus.txt
	expect_fail "$tool clash plugin" "plugin clash_quad.so: shape keyword 'quad' is already defined by $P/quad.so" \
		"${run[@]}" --plugin "$P/quad.so" --plugin clash_quad.so torus.txt
	expect_fail "$tool same name" "plugin quad-copy.so: a plugin named 'quad' is already loaded from $P/quad.so" \
		"${run[@]}" --plugin "$P/quad.so" --plugin quad-copy.so torus.txt
	expect_fail "$tool init fails" "plugin init_fails.so: init failed (whitted_plugin_init returned -1)" \
		"${run[@]}" --plugin init_fails.so torus.txt
	# A refused plugin after a good one (the good one's strings are its
	# own: freed once, no abort).
	expect_fail "$tool good then not ELF" "plugin text.so: not a plugin" \
		"${run[@]}" --plugin "$P/quad.so" --plugin text.so torus.txt
	expect_fail "$tool good then no entry" "plugin no_entry.so: not a whitted plugin" \
		"${run[@]}" --plugin "$P/quad.so" --plugin no_entry.so torus.txt
	expect_fail "$tool good then abi" "plugin bad_abi.so: built for plugin ABI version 99" \
		"${run[@]}" --plugin "$P/quad.so" --plugin bad_abi.so torus.txt
	cp text.so dir/text.so
	expect_fail "$tool path dir" "plugin dir/text.so: not a plugin" \
		env WHITTED_PLUGIN_PATH="$T/none:dir" "${run[@]}" torus.txt
	rm -f dir/text.so
done
rm -f dir/text.so
cp text.so dir/text.so
expect_fail "merge bad plugin" "plugin $T/dir/text.so: not a plugin" \
	env WHITTED_PLUGIN_PATH="$T/dir" "$W" merge -o out.png nothing.png
rm -f dir/text.so
for bad_so in text.so no_entry.so bad_abi.so; do
	expect_fail "merge good then $bad_so" "plugin $bad_so: " \
		"$W" merge --plugin "$P/quad.so" --plugin $bad_so -o out.png nothing.png
done
mkdir -p gooddir && cp "$P/quad.so" gooddir/a.so && cp text.so gooddir/b.so
expect_fail "path: a good a.so, a stray b.so" "plugin $T/gooddir/b.so: not a plugin" \
	env WHITTED_PLUGIN_PATH="$T/gooddir" "$W" -s 16 -o out.png torus.txt
rm -rf gooddir
expect_fail "merge missing plugin" "plugin nowhere.so: No such file or directory" \
	"$W" merge --plugin nowhere.so -o out.png nothing.png
expect_fail "merge plugin init fails" "plugin init_fails.so: init failed" \
	"$W" merge --plugin init_fails.so -o out.png nothing.png
# A plugin refused after dlopen (its keyword clashes) is closed again and
# leaks nothing, nor does one whose init fails.
if command -v valgrind >/dev/null 2>&1; then
	for so in clash_sphere init_fails text no_entry bad_abi; do
		valgrind -q --leak-check=full --show-leak-kinds=all --errors-for-leak-kinds=all \
			--error-exitcode=99 "$W" --plugin "$P/quad.so" --plugin $so.so -o out.png torus.txt 2>vg.log
		rc=$?
		grep -v '^whitted: error: plugin' vg.log >vg-only.log
		check "valgrind: $so refused, exit 1, clean ($(head -c 300 vg-only.log))" [ $rc -eq 1 -a ! -s vg-only.log ]
	done
	# Every tool, a good plugin then a bad one.
	for so in text no_entry bad_abi; do
		for tool in scene2pov whitted-view merge; do
			case $tool in
			scene2pov) run=("$S2P" -o out.pov --plugin "$P/quad.so" --plugin $so.so torus.txt) ;;
			whitted-view) run=("$VIEW" --plugin "$P/quad.so" --plugin $so.so torus.txt) ;;
			merge) run=("$W" merge --plugin "$P/quad.so" --plugin $so.so -o out.png nothing.png) ;;
			esac
			valgrind -q --leak-check=full --show-leak-kinds=all --errors-for-leak-kinds=all \
				--error-exitcode=99 "${run[@]}" 2>vg.log
			rc=$?
			grep -v ': error: plugin ' vg.log >vg-only.log
			check "valgrind: $tool, quad then $so, exit 1, clean ($(head -c 300 vg-only.log))" \
				[ $rc -eq 1 -a ! -s vg-only.log ]
		done
	done
else
	bad "valgrind on a refused plugin" "NOT RUN: valgrind is not installed (make deps)"
fi
# A plugin cut short (the first 600 bytes of a good one: an interrupted
# copy), which dlopen would map and die of with SIGBUS, and one of another
# processor: refused before dlopen, by every tool.
head -c 600 "$P/torus.so" >cut.so
cp "$P/torus.so" foreign.so
if [ "$(uname -m)" = x86_64 ]; then
	printf '\267\000' | dd of=foreign.so bs=1 seek=18 conv=notrunc 2>/dev/null
	foreign="built for aarch64, this is x86-64"
else
	printf '\076\000' | dd of=foreign.so bs=1 seek=18 conv=notrunc 2>/dev/null
	foreign="built for x86-64, this is"
fi
for tool in whitted scene2pov whitted-view merge; do
	case $tool in
	whitted) run=("$W" -s 16 -o out.png) ;;
	scene2pov) run=("$S2P" -o out.pov) ;;
	whitted-view) [ -x "$VIEW" ] || continue; run=("$VIEW") ;;
	merge) run=("$W" merge -o out.png) ;;
	esac
	expect_fail "$tool cut short" "plugin cut.so: not a plugin: the file is cut short (a segment reaches byte" \
		"${run[@]}" --plugin cut.so torus.txt
	expect_fail "$tool another processor" "plugin foreign.so: $foreign" \
		"${run[@]}" --plugin foreign.so torus.txt
done
# The loader's test compiles without -Wformat-truncation's warning however
# deep the checkout (its expected message was a fixed buffer).
deep=$(printf '/a-rather-deep-checkout%.0s' $(seq 12))/build/plugins
"$CC" -std=c99 -Wall -Wextra -Wpedantic -Werror -O2 -I"$ROOT/include" -I"$ROOT/src" -I"$ROOT/tests/unit" \
	-DRT_TEST_PLUGIN_DIR="\"$deep\"" -c -o test_loader.o "$ROOT/tests/unit/plugin/test_loader.c" 2>cc.log
check "test_loader.c in a deep checkout: no warning ($(head -c 300 cc.log))" [ $? -eq 0 -a ! -s cc.log ]

# Plugins whose methods break their contract (tests/plugins/hostile.c):
# each is the plugin's error, located at the object's keyword for parse,
# exit 1, nothing written, and never a crash.
printf '1\n16\n\n1\nblob\n0 0 20\n0.9 0.2 0.2\n0.1 0.5 0.4 0.0\n10\n\n1\n-100 -150 200\n1 1 1\n' >blob.txt
for v in NONE PARSE_ZERO PARSE_POSITIVE PARSE_SILENT PARSE_ODD_ERROR PARSE_ALIEN EXPORT_POSITIVE \
	EXPORT_SILENT TESS_POSITIVE; do
	build hostile_$v.so -D$v "$ROOT/tests/plugins/hostile.c" -lm
	check "hostile.c builds with -D$v" [ $? -eq 0 ]
done
"$W" -q -s 16 --plugin ./hostile_NONE.so -o out.png blob.txt
check "the well-behaved blob renders" [ $? -eq 0 -a -s out.png ]
rm -f out.png
for case in "PARSE_ZERO:its parse returned 0 (success) without a shape" \
	"PARSE_POSITIVE:its parse returned 7, which is neither 0 (a shape) nor a negative error" \
	"PARSE_SILENT:its parse failed without a message (it returned an error without calling host->fail)" \
	"PARSE_ALIEN:its parse returned a shape whose table is not 'blob''s own"; do
	v=${case%%:*} msg=${case#*:}
	for tool in whitted scene2pov whitted-view; do
		case $tool in
		whitted) run=("$W" -s 16 -o out.png) ;;
		scene2pov) run=("$S2P" -o out.pov) ;;
		whitted-view) [ -x "$VIEW" ] || continue; run=("$VIEW") ;;
		esac
		expect_fail "$tool $v" "^blob.txt:5:1: error: object 'blob' of the plugin ./hostile_$v.so: $msg" \
			"${run[@]}" --plugin ./hostile_$v.so blob.txt
	done
done
# A parse error of a kind no parse returns (-RT_E_INVALID, a usage error's)
# is still the scene's: exit 1, not 2.
expect_fail "whitted PARSE_ODD_ERROR" "^blob.txt:5:1: error: blob: an error of the wrong kind" \
	"$W" -s 16 -o out.png --plugin ./hostile_PARSE_ODD_ERROR.so blob.txt
expect_fail "scene2pov EXPORT_POSITIVE" \
	"out.pov: object 1 ('blob' of the plugin ./hostile_EXPORT_POSITIVE.so): its export_pov returned neither 0 nor an error (returned 3)" \
	"$S2P" -o out.pov --plugin ./hostile_EXPORT_POSITIVE.so blob.txt
expect_fail "scene2pov EXPORT_SILENT" \
	"out.pov: object 1 ('blob' of the plugin ./hostile_EXPORT_SILENT.so): its export_pov failed (returned -4)" \
	"$S2P" -o out.pov --plugin ./hostile_EXPORT_SILENT.so blob.txt
check "scene2pov EXPORT_*: no .ini left" [ ! -e out.ini ]
if command -v valgrind >/dev/null 2>&1; then
	for v in PARSE_ZERO PARSE_POSITIVE PARSE_SILENT PARSE_ALIEN; do
		valgrind -q --leak-check=full --show-leak-kinds=all --errors-for-leak-kinds=all \
			--error-exitcode=99 "$W" -s 16 --plugin ./hostile_$v.so -o out.png blob.txt 2>vg.log
		rc=$?
		grep -v '^blob.txt:5:1: error: ' vg.log >vg-only.log
		check "valgrind: hostile $v, exit 1, clean ($(head -c 300 vg-only.log))" [ $rc -eq 1 -a ! -s vg-only.log ]
	done
fi

# Without the plugin, the keyword is unknown (the message says a plugin
# may provide it).
expect_fail "no plugin" "8:1: error: unknown object 'torus'.*needs a plugin" "$W" -s 16 -o out.png torus.txt

# Loading: the option, the path (a missing directory skipped), the same
# file twice, and the list.
"$W" -q -s 48 -j1 --plugin "$P/torus.so" -o j1.png torus.txt
check "renders with --plugin" [ $? -eq 0 -a -s j1.png ]
WHITTED_PLUGIN_PATH="$T/none::$T/dir" "$W" -q -s 48 -o env.png torus.txt
check "renders with WHITTED_PLUGIN_PATH" cmp -s j1.png env.png
WHITTED_PLUGIN_PATH="$T/dir" "$W" -q -s 48 --plugin dir/torus.so -o twice.png torus.txt
check "the same file twice is loaded once" cmp -s j1.png twice.png
"$W" --list-shapes --plugin "$P/quad.so" --plugin "$P/cylinder.so" >list.txt 2>err
check "--list-shapes exits 0" [ $? -eq 0 ]
check "--list-shapes: built-ins" grep -q '^sphere  *built-in  dialects: classic,spot,pyramid,nearfar$' list.txt
check "--list-shapes: the pyramid's two tables" [ "$(grep -c '^pyramid ' list.txt)" -eq 2 ]
check "--list-shapes: a plugin's origin" \
	grep -q "^quad  *plugin quad 1.0 ($P/quad.so)  dialects: classic,spot,pyramid,nearfar$" list.txt
check "--list-shapes: every plugin" grep -q "^cylinder  *plugin cylinder 1.0 ($P/cylinder.so)" list.txt
check "--list-shapes lists no torus unloaded" bash -c '! grep -q "^torus" list.txt'
# --list-shapes renders nothing: a SCENE or a render option with it is a
# usage error (exit 2), not silently ignored.
for args in "/nonexistent.txt -o x.png --tile 3" "torus.txt" "-o x.png" "--test-scene" "-s 10" "-j 2"; do
	rm -f x.png
	"$W" --list-shapes $args >list-out.txt 2>err
	rc=$?
	first=${args%% *}
	if [ "$first" = "${first#-}" ]; then want="--list-shapes takes no SCENE, found '$first'"
	else want="--list-shapes takes only --plugin and -q, found $first"; fi
	check "--list-shapes $args: exit 2 ($rc), '$want' ($(head -c 200 err))" \
		bash -c "[ $rc -eq 2 ] && grep -qF -- \"whitted: error: $want\" err && [ ! -s list-out.txt ] && [ ! -e x.png ]"
done
"$W" --list-shapes -q --plugin "$P/quad.so" >list-out.txt 2>err
check "--list-shapes -q --plugin is fine" bash -c "[ $? -eq 0 ] && grep -q '^quad ' list-out.txt"
expect_fail "--list-shapes bad plugin" "plugin text.so: not a plugin" "$W" --list-shapes --plugin text.so
"$W" --help | grep -q -- "--plugin FILE.so" && "$S2P" --help | grep -q -- "--plugin FILE.so" &&
	"$W" --help | grep -q -- "--list-shapes" && "$W" merge --help | grep -q -- "--plugin FILE.so"
check "--help names --plugin and --list-shapes" [ $? -eq 0 ]

# The course's student file with ten quads (refused at 65:1 without the
# plugin: tests/cli/dialects.sh; matched against POV-Ray by povcheck).
"$W" -s 32 --plugin "$P/quad.so" -o abir.png "$DATA/course-files/abir66-quad.txt" 2>err
check "abir66-quad.txt renders with the quad plugin ($(head -c 200 err))" [ $? -eq 0 -a -s abir.png ]

# Threads and tiles: the same image.
"$W" -q -s 48 -j2 --plugin "$P/torus.so" -o j2.png torus.txt &&
	"$W" -q -s 48 -j7 --plugin "$P/torus.so" -o j7.png torus.txt
check "-j1, -j2, -j7 give the same image" bash -c 'cmp -s j1.png j2.png && cmp -s j1.png j7.png'
for k in 1 2 3 4; do
	"$W" -q -s 48 -j2 --plugin "$P/torus.so" --grid 2x2 --tile $k -o tile-$k.png torus.txt || bad tile "tile $k"
done
"$W" merge -o merged.png tile-*.png
check "tiles merged give the same image" cmp -s j1.png merged.png
"$W" merge --plugin "$P/torus.so" -o merged2.png tile-*.png
check "merge --plugin of the same file" cmp -s j1.png merged2.png
strings tile-1.png | grep -q "plugins=torus@1.0#[0-9a-f]\{16\}"
check "a tile records the plugin" [ $? -eq 0 ]
"$W" -q -s 48 --plugin "$P/torus.so" --plugin "$P/quad.so" --grid 2x2 --tile 1 -o both.png torus.txt
check "a tile records only the plugins its scene uses" bash -c \
	'strings both.png | grep -q "plugins=torus@1.0#[0-9a-f]\{16\}" && ! strings both.png | grep -q "quad@"'
# Another build of the torus (another version string: another file).
sed 's/{ "torus", "1.0", torus_shapes }/{ "torus", "1.1", torus_shapes }/' "$ROOT/plugins/torus.c" >torus11.c
build torus11.so torus11.c -lm
check "the torus 1.1 builds" [ $? -eq 0 ]
"$W" -q -s 48 --plugin torus11.so --grid 2x2 --tile 2 -o tile-2.png torus.txt
expect_fail "merge: other plugins" "tile-2.png: made with other plugins than tile-1.png (torus@1.1#[0-9a-f]*, not torus@1.0#" \
	"$W" merge -o out.png tile-1.png tile-2.png tile-3.png tile-4.png
expect_fail "merge --plugin: another build" "tile-1.png: made with another plugin 'torus' than torus11.so (torus@1.0#" \
	"$W" merge --plugin torus11.so -o out.png tile-1.png tile-3.png tile-4.png
# --plugin overrides WHITTED_PLUGIN_PATH: a .so of the path with the name
# or a keyword of a named one is skipped, with a note.
mkdir -p over && cp torus11.so over/torus11.so && cp clash_quad.so over/clash_quad.so
WHITTED_PLUGIN_PATH="$T/over" "$W" -s 48 -j2 --plugin "$P/torus.so" --plugin "$P/quad.so" --grid 2x2 --tile 2 \
	-o over-2.png torus.txt 2>err
check "--plugin wins over the path's plugin of the same name (exit 0: $(head -c 300 err))" \
	bash -c "[ $? -eq 0 ] && strings over-2.png | grep -q 'plugins=torus@1.0#'"
check "the note names the skipped plugin" \
	grep -q "^whitted: note: plugin $T/over/torus11.so skipped: a plugin named 'torus' is already loaded from $P/torus.so$" err
check "the note names the skipped keyword" \
	grep -q "^whitted: note: plugin $T/over/clash_quad.so skipped: its shape keyword 'quad' is already defined by $P/quad.so$" err
WHITTED_PLUGIN_PATH="$T/over" "$W" -q -s 48 --plugin "$P/torus.so" --plugin "$P/quad.so" -o quiet.png torus.txt 2>err
check "-q silences the note" [ $? -eq 0 -a ! -s err ]
WHITTED_PLUGIN_PATH="$T/over" "$S2P" --plugin "$P/torus.so" -o over.pov torus.txt 2>err
check "scene2pov: --plugin wins over the path" bash -c "[ $? -eq 0 ] && grep -q 'skipped' err && [ -s over.pov ]"
WHITTED_PLUGIN_PATH="$T/over" "$W" --list-shapes --plugin "$P/torus.so" >list2.txt 2>err
check "--list-shapes: the named torus, not the path's" grep -q "^torus  *plugin torus 1.0 ($P/torus.so)" list2.txt
# Only the path: its own clash is still an error; so is one between two
# named files (above: same name).
rm -rf over
mkdir -p pp && cp "$P/quad.so" pp/a.so && cp clash_quad.so pp/b.so
expect_fail "a clash within the path is an error" "plugin $T/pp/b.so: shape keyword 'quad' is already defined by $T/pp/a.so" \
	env WHITTED_PLUGIN_PATH="$T/pp" "$W" -s 16 -o out.png torus.txt
rm -rf pp
# merge checks the tiles against the --plugin files only: the path's
# torus 1.1 does not make it refuse tiles of torus 1.0.
mkdir -p p11 && cp torus11.so p11/
"$W" -q -s 48 -j2 --plugin "$P/torus.so" --grid 2x2 --tile 2 -o tile-2.png torus.txt
WHITTED_PLUGIN_PATH="$T/p11" "$W" merge -o merged3.png tile-1.png tile-2.png tile-3.png tile-4.png 2>err
check "merge ignores the path's plugins when checking ($(head -c 200 err))" cmp -s j1.png merged3.png
expect_fail "merge: --plugin still checked with a path set" "made with another plugin 'torus' than torus11.so" \
	env WHITTED_PLUGIN_PATH="$T/p11" "$W" merge --plugin torus11.so -o out.png tile-1.png tile-2.png tile-3.png tile-4.png
rm -rf p11
"$W" -q -s 48 --grid 2x2 --tile 2 -o plain-2.png "$ROOT/scenes/sphere.txt" &&
	"$W" -q -s 48 --plugin "$P/torus.so" --grid 2x2 --tile 2 -o plain-2b.png "$ROOT/scenes/sphere.txt"
check "a tile of a scene without plugin shapes is the same with plugins loaded" cmp -s plain-2.png plain-2b.png

# scene2pov exports each plugin's shapes.
for so in quad cylinder torus; do
	"$S2P" -q --plugin "$P/$so.so" -o $so.pov "$ROOT/scenes/plugins/$so.txt" || bad "scene2pov $so" "failed"
done
check "scene2pov: quad as a mesh" grep -q '^mesh {' quad.pov
check "scene2pov: cylinder" grep -q '^cylinder { <' cylinder.pov
check "scene2pov: torus with sturm and a matrix" bash -c 'grep -q "^torus { 35, 10 sturm" torus.pov && grep -q "matrix <" torus.pov'
finish
