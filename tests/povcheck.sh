#!/bin/sh
# The cross-validation against POV-Ray 3.7: renders every scene in scenes/,
# some camera, floor and recursion variants, and the renderable real-world
# scenes of ../shared/real-scenes, with `whitted --clamp final` and with
# POV-Ray from scene2pov's export, and compares them with imgcmp's gate
# (PSNR >= 60 dB, <= 0.2% of pixels off by >2 levels, <= 0.02% by >8).
# Then checks the default clamping against --clamp final.  Prints a table;
# fails when any comparison fails.  Outputs stay in build/povcheck/.
#   tests/povcheck.sh            everything
#   tests/povcheck.sh PATTERN    only the cases whose name contains PATTERN
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build"
out="$build/povcheck"
size=${POVCHECK_SIZE:-160}
filter=${1:-}

if ! command -v povray >/dev/null 2>&1; then
	echo "povcheck: NOT RUN: povray is not installed (apt-get install povray); nothing was compared"
	exit 1
fi
for tool in whitted scene2pov imgcmp; do
	if [ ! -x "$build/$tool" ]; then
		echo "povcheck: $build/$tool is missing; run 'make all' first" >&2
		exit 1
	fi
done
rm -rf "$out"
mkdir -p "$out" || exit 1

pass=0 fail=0 failed=""

# Debian's povray wants a per-user configuration directory and says so on
# every run; a private HOME keeps that noise (and any user's povray.ini
# settings) out of the comparison.
mkdir -p "$out/home"

# case NAME SCENE [OPTIONS...]: one row of the table.
case_run() {
	name=$1 scene=$2
	shift 2
	case "$name" in *"$filter"*) ;; *) return 0 ;; esac
	w="$out/$name-whitted.png"
	log="$out/$name.log"
	if ! "$build/whitted" -q --clamp final -s "$size" "$@" "$scene" -o "$w" >"$log" 2>&1 ||
	   ! "$build/scene2pov" -q -s "$size" "$@" "$scene" -o "$out/$name.pov" >>"$log" 2>&1 ||
	   ! (cd "$out" && HOME="$out/home" povray "$name.ini" +WT2 -V >>"$log" 2>&1); then
		printf '%-34s %s\n' "$name" "ERROR (see $log)"
		tail -5 "$log" | sed 's/^/    /'
		fail=$((fail + 1))
		failed="$failed $name"
		return 0
	fi
	if result=$("$build/imgcmp" --diff "$out/$name-diff.png" "$w" "$out/$name.png" 2>>"$log"); then
		status=ok
		pass=$((pass + 1))
	else
		status="FAIL (difference x32: $out/$name-diff.png)"
		fail=$((fail + 1))
		failed="$failed $name"
	fi
	# psnr=X mean=X max=X off2=X% off8=X% PASS|FAIL
	set -- $(printf '%s\n' "$result" | sed 's/[a-z0-9]*=//g')
	printf '%-34s %8s %5s %9s %9s  %s\n' "$name" "${1:-?}" "${3:-?}" "${4:-?}" "${5:-?}" "$status"
}

printf '%-34s %8s %5s %9s %9s  %s\n' "case (${size}x${size})" "PSNR dB" "max" ">2 levels" ">8 levels" "result"
for scene in "$root"/scenes/*.txt; do
	case_run "$(basename "$scene" .txt)" "$scene"
done
s="$root/scenes"
case_run scene-rolled "$s/scene.txt" --up 0.5,0,1
case_run scene-above "$s/scene.txt" --eye 120,-160,140 --look 0,20,20 --fov 60
case_run scene-below-floor "$s/scene.txt" --eye -40,-150,-30 --look 0,0,20
case_run scene-floor-300-7 "$s/scene.txt" --floor 300,7
case_run sphere-no-floor "$s/sphere.txt" --no-floor --eye 0,-150,120 --look 0,0,30
case_run quadric-above "$s/quadric.txt" --eye 40,-170,130 --look 0,30,30 --fov 70
case_run quadric-inside-eye-inside "$s/quadric-inside.txt" --eye 0,-20,40 --look 0,40,20 --fov 100
for r in 1 2 3 4 5; do
	case_run "mirrors-r$r" "$s/mirrors.txt" -r "$r"
done
case_run mirrors-r3-rolled "$s/mirrors.txt" -r 3 --eye 60,-180,60 --look 0,30,50 --up -0.4,0,1 --fov 65
case_run test-scene --test-scene

# Real-world files (not ours), when the shared directory is beside the repo.
real="$root/../shared/real-scenes"
if [ -d "$real" ]; then
	for f in anachor pistachio102 adibashaira ajakil mdraihansobhan; do
		[ -f "$real/$f.txt" ] && case_run "real-$f" "$real/$f.txt"
	done
else
	echo "povcheck: real scenes NOT RUN: $real is missing (clone shared/ beside the repo)"
fi

# The default clamping.  bright-reflection's mirror sees a surface brighter
# than 1, so clamping at every level must change its image; in the others
# named here no reflected colour exceeds 1, so the two modes must give
# byte-identical images, as every scene must at recursion 1 (no
# reflections).
clamp_pair() {
	name=$1 expect=$2 scene=$3
	shift 3
	case "clamp-$name" in *"$filter"*) ;; *) return 0 ;; esac
	"$build/whitted" -q -s "$size" "$@" "$scene" -o "$out/clamp-$name-level.png" &&
	"$build/whitted" -q -s "$size" --clamp final "$@" "$scene" -o "$out/clamp-$name-final.png" || {
		printf '%-34s %s\n' "clamp-$name" "ERROR"
		fail=$((fail + 1))
		failed="$failed clamp-$name"
		return 0
	}
	if cmp -s "$out/clamp-$name-level.png" "$out/clamp-$name-final.png"; then got=identical; else got=different; fi
	if [ "$got" = "$expect" ]; then
		pass=$((pass + 1))
		printf '%-34s %s\n' "clamp-$name" "ok (level and final $got)"
	else
		fail=$((fail + 1))
		failed="$failed clamp-$name"
		printf '%-34s %s\n' "clamp-$name" "FAIL (level and final $got, expected $expect)"
	fi
}
clamp_pair bright-reflection different "$s/bright-reflection.txt"
for n in scene sphere triangle shadows backlit; do
	clamp_pair "$n" identical "$s/$n.txt"
done
for scene in "$s"/*.txt; do
	clamp_pair "$(basename "$scene" .txt)-r1" identical "$scene" -r 1
done

echo "povcheck: $pass passed, $fail failed"
[ "$fail" -eq 0 ] || { echo "povcheck: failing:$failed"; exit 1; }
