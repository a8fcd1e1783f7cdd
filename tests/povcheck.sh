#!/bin/sh
# The cross-validation against POV-Ray 3.7: renders every scene in scenes/
# (each in its own dialect; a scene whose lights fall off is measured, not
# gated, see below), some camera, floor and recursion variants, and the
# renderable real-world scenes of tests/data/real-scenes (each of which must
# be there), with `whitted --clamp final` and with POV-Ray from scene2pov's
# export, and compares them with imgcmp's gate (PSNR >= 60 dB, <= 0.2% of
# pixels off by >2 levels, <= 0.02% by >8).  Checks the camera apart from
# the exporter (quadrants of a known scene, and a POV-Ray camera written
# here, also for the nearfar camera's wider view), then the default
# clamping against --clamp final.  Prints a table; fails when any
# comparison fails or cannot be made.  Outputs stay in build/povcheck/.
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
	echo "povcheck: 0 passed, 1 failed, 0 skipped"
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

# render_both NAME SCENE [OPTIONS...]: whitted's image ($w) and POV-Ray's
# of scene2pov's export ($out/NAME.png) at size, what they said in $log;
# fails when any of the three does.
render_both() {
	name=$1 scene=$2
	shift 2
	w="$out/$name-whitted.png"
	log="$out/$name.log"
	"$build/whitted" -q --clamp final -s "$size" "$@" "$scene" -o "$w" >"$log" 2>&1 &&
		"$build/scene2pov" -q -s "$size" "$@" "$scene" -o "$out/$name.pov" >>"$log" 2>&1 &&
		(cd "$out" && HOME="$out/home" povray "$name.ini" +WT2 -V >>"$log" 2>&1)
}

# table_row NAME RESULT STATUS: the table's row of imgcmp's RESULT.
table_row() {
	row_name=$1 row_status=$3
	# psnr=X mean=X max=X off2=X% off8=X% PASS|FAIL
	# shellcheck disable=SC2046
	set -- $(printf '%s\n' "$2" | sed 's/[a-z0-9]*=//g')
	printf '%-34s %8s %5s %9s %9s  %s\n' "$row_name" "${1:-?}" "${3:-?}" "${4:-?}" "${5:-?}" \
		"$row_status"
}

# gate NAME POV_IMAGE OK_STATUS: imgcmp's gate on whitted's image ($w)
# against POV_IMAGE, counted, and its row.
gate() {
	if result=$("$build/imgcmp" --diff "$out/$1-diff.png" "$w" "$2" 2>>"$log"); then
		status=$3
		pass=$((pass + 1))
	else
		status="FAIL (difference x32: $out/$1-diff.png)"
		fail=$((fail + 1))
		failed="$failed $1"
	fi
	table_row "$1" "$result" "$status"
}

# case NAME SCENE [OPTIONS...]: one row of the table.
case_run() {
	case "$1" in *"$filter"*) ;; *) return 0 ;; esac
	if ! render_both "$@"; then
		printf '%-34s %s\n' "$name" "ERROR (see $log)"
		tail -5 "$log" | sed 's/^/    /'
		fail=$((fail + 1))
		failed="$failed $name"
		return 0
	fi
	gate "$name" "$out/$name.png" ok
}

# missing NAME WHY: a row for a comparison that could not be made, which
# fails the run.
missing() {
	case "$1" in *"$filter"*) ;; *) return 0 ;; esac
	printf '%-34s %s\n' "$1" "FAIL (not compared: $2)"
	fail=$((fail + 1))
	failed="$failed $1"
}

# quadrant_row NAME IMAGE TL TR BL BR: a row for tests/tools/quadrants.py.
quadrant_row() {
	row=$1 img=$2
	shift 2
	if result=$(python3 "$root/tests/tools/quadrants.py" "$img" "$@" 2>&1); then
		printf '%-34s %s\n' "$row" "ok (each sphere in its quadrant)"
		pass=$((pass + 1))
	else
		printf '%-34s %s\n' "$row" "FAIL"
		printf '%s\n' "$result" | sed 's/^/    /'
		fail=$((fail + 1))
		failed="$failed $row"
	fi
}

# measure NAME SCENE [OPTIONS...]: case_run's comparison for a scene that
# POV-Ray cannot render exactly (a light's falloff, see the falloff note
# below): the row says the difference and fails only when the comparison
# cannot be made.
measure() {
	case "$1" in *"$filter"*) ;; *) return 0 ;; esac
	if ! render_both "$@"; then
		missing "$name" "whitted, scene2pov or povray failed (see $log)"
		return 0
	fi
	result=$("$build/imgcmp" --diff "$out/$name-diff.png" "$w" "$out/$name.png" 2>>"$log")
	pass=$((pass + 1))
	table_row "$name" "$result" "measured, not gated (falloff: POV-Ray's fade is not exp(-k d^2))"
}

# camera_case NAME SCENE ASPECT EYE LOOK UP FOV TL TR BL BR: see "The
# camera" below.  ASPECT 0 is the square view; otherwise the scene's own
# (nearfar) header must give that ASPECT.
camera_case() {
	cam=$1 scene=$2 aspect=$3 eye=$4 look=$5 up=$6 fov=$7
	shift 7
	case "$cam" in *"$filter"*) ;; *) return 0 ;; esac
	log="$out/$cam.log"
	opts="--no-floor --eye $eye --look $look --up $up --fov $fov"
	# shellcheck disable=SC2086
	if ! "$build/whitted" -q -s "$size" $opts "$scene" -o "$out/$cam-whitted.ppm" >"$log" 2>&1 ||
	   ! "$build/scene2pov" -q -s "$size" $opts "$scene" -o "$out/$cam.pov" >>"$log" 2>&1 ||
	   ! (cd "$out" && HOME="$out/home" povray "$cam.ini" +FP "+O$cam-export.ppm" +WT2 -V \
		>>"$log" 2>&1); then
		missing "$cam" "whitted, scene2pov or povray failed (see $log)"
		return 0
	fi
	# The camera of scene-format.md, computed here: forward = the unit
	# vector from the eye to the look-at point, right = forward x up
	# normalised, up' = right x forward; POV-Ray's explicit camera shoots
	# direction + (u - 1/2) right + (1/2 - v) up for the image point
	# (u, v) from the top left, so with |direction| = 1 / (2 tan(fov / 2))
	# and unit right and up the image spans the field of view; the
	# nearfar rule FOVX = ASPECT FOVY lengthens right to
	# tan(FOVX / 2) / tan(FOVY / 2).
	echo "$eye $look $up $fov $aspect" | tr ',' ' ' | awk '
	function tan_half(deg) { return sin(deg * 3.14159265358979 / 360) / cos(deg * 3.14159265358979 / 360) }
	{
		fx = $4 - $1; fy = $5 - $2; fz = $6 - $3
		n = sqrt(fx * fx + fy * fy + fz * fz); fx /= n; fy /= n; fz /= n
		rx = fy * $9 - fz * $8; ry = fz * $7 - fx * $9; rz = fx * $8 - fy * $7
		n = sqrt(rx * rx + ry * ry + rz * rz); rx /= n; ry /= n; rz /= n
		ux = ry * fz - rz * fy; uy = rz * fx - rx * fz; uz = rx * fy - ry * fx
		d = 0.5 / tan_half($10)
		if ($11 > 0) { k = tan_half($11 * $10) / tan_half($10); rx *= k; ry *= k; rz *= k }
		printf "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\nbackground { rgb 0 }\n"
		printf "camera { perspective location <%.17g,%.17g,%.17g>\n", $1, $2, $3
		printf "  direction <%.17g,%.17g,%.17g>\n", d * fx, d * fy, d * fz
		printf "  right <%.17g,%.17g,%.17g> up <%.17g,%.17g,%.17g> }\n", rx, ry, rz, ux, uy, uz
		printf "#declare Flat = finish { ambient 1 diffuse 0 phong 0 reflection 0 }\n"
		printf "sphere { <60,0,60>, 25 pigment { rgb <1,0,0> } finish { Flat } }\n"
		printf "sphere { <-60,0,60>, 25 pigment { rgb <0,0,1> } finish { Flat } }\n"
		printf "sphere { <-60,0,-40>, 25 pigment { rgb <0,1,0> } finish { Flat } }\n"
		printf "sphere { <60,0,-40>, 25 pigment { rgb <1,1,0> } finish { Flat } }\n"
		if ($11 > 0) {
			printf "sphere { <-150,0,10>, 20 pigment { rgb <0,1,1> } finish { Flat } }\n"
			printf "sphere { <150,0,10>, 20 pigment { rgb <1,0,1> } finish { Flat } }\n"
		}
	}' >"$out/$cam-own.pov"
	if ! (cd "$out" && HOME="$out/home" povray "+I$cam-own.pov" "+O$cam-own.ppm" +FP \
		"+W$size" "+H$size" -A -D +WT2 -V >>"$log" 2>&1); then
		missing "$cam-own-camera" "povray failed on $out/$cam-own.pov (see $log)"
		return 0
	fi
	quadrant_row "$cam-whitted" "$out/$cam-whitted.ppm" "$@"
	quadrant_row "$cam-pov-export" "$out/$cam-export.ppm" "$@"
	quadrant_row "$cam-pov-own-camera" "$out/$cam-own.ppm" "$@"
	if "$build/imgcmp" "$out/$cam-whitted.ppm" "$out/$cam-own.ppm" >>"$log" 2>&1; then
		printf '%-34s %s\n' "$cam-whitted-vs-own" "ok (whitted = POV-Ray with the test's camera)"
		pass=$((pass + 1))
	else
		printf '%-34s %s\n' "$cam-whitted-vs-own" "FAIL (see $log)"
		fail=$((fail + 1))
		failed="$failed $cam-whitted-vs-own"
	fi
}

printf '%-34s %8s %5s %9s %9s  %s\n' "case (${size}x${size})" "PSNR dB" "max" ">2 levels" ">8 levels" "result"
# Every scene, in its own dialect, but those whose lights fall off: POV-Ray
# has no exp(-k d^2) light, and scene2pov writes the nearest fade it has
# (pov_export/export.c says how near), so those are measured here and
# gated against the reference renderer (make refcheck) instead.  Their
# geometry, camera and cones are gated here at falloff 0 (nearfar.txt).
for scene in "$root"/scenes/*.txt; do
	case "$(basename "$scene")" in
	falloff*) measure "$(basename "$scene" .txt)" "$scene" ;;
	*) case_run "$(basename "$scene" .txt)" "$scene" ;;
	esac
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
# The dialects from other places: the spot dialect's cones seen from above
# (the 125-degree one through its point light less its dark back cone), the
# pyramid dialect's 90-degree view and 30-wide tiles from above and with
# the square pyramids' faces at grazing angles, the nearfar camera (near
# plane, FOVX = 1.3 FOVY) from above and rolled, over the infinite
# checkerboard out to its horizon (the eye 8 above it, so that the near
# plane, 12 ahead, stays above the floor: below it whitted would rightly
# not see the floor that POV-Ray does).
case_run spot-above "$s/spot.txt" --eye 0,-220,260
case_run spot-r1-wide "$s/spot.txt" -r 1 --eye -200,-120,80 --look 0,20,20 --fov 100
case_run pyramid-above "$s/pyramid.txt" --eye 120,-180,160 --look 0,20,20
case_run pyramid-low "$s/pyramid.txt" --eye -150,-60,8 --look 30,40,20 --fov 60
case_run nearfar-above "$s/nearfar.txt" --eye 60,-260,140
case_run nearfar-rolled "$s/nearfar.txt" --eye -160,-160,60 --look 0,0,20 --up 0.3,0,1
case_run nearfar-horizon "$s/nearfar.txt" --eye 0,-300,8 --look 0,0,8

# Real-world files (not ours), copied into tests/data/.
# Each listed file must be there: a missing one fails the run, since a
# comparison that was not made must not read as passed.
real="$root/tests/data/real-scenes"
for f in anachor pistachio102 adibashaira ajakil mdraihansobhan; do
	if [ -f "$real/$f.txt" ]; then
		case_run "real-$f" "$real/$f.txt"
	else
		missing "real-$f" "$real/$f.txt is missing"
	fi
done

# The course's own files of the spot and pyramid dialects (no falloff:
# POV-Ray can express them exactly).  The nearfar ones, whose lights fall
# off, are gated against the reference renderer by refcheck.
course="$root/tests/data/course-files"
for f in munzer2 sadathossain01 ishtiaqniloy; do
	if [ -f "$course/$f.txt" ]; then
		case_run "course-$f" "$course/$f.txt"
	else
		missing "course-$f" "$course/$f.txt is missing"
	fi
done

# The example plugins (make plugins): each one's scene of scenes/plugins/
# from outside, the torus and the cylinder also at grazing angles (the eye
# in the torus's plane, along the column's side and in the plane of its
# cap), and the course's student file with ten quads.
pl="$build/plugins"
if [ -f "$pl/quad.so" ] && [ -f "$pl/cylinder.so" ] && [ -f "$pl/torus.so" ]; then
	p="$root/scenes/plugins"
	case_run plugin-quad "$p/quad.txt" --plugin "$pl/quad.so" --eye 0,-160,90 --look 10,20,20 --fov 60
	case_run plugin-cylinder "$p/cylinder.txt" --plugin "$pl/cylinder.so" --eye 40,-150,110 --look 0,20,25 --fov 60
	case_run plugin-cylinder-along-side "$p/cylinder.txt" --plugin "$pl/cylinder.so" \
		--eye -35.2,20,220 --look -35.2,20,0 --up 0,1,0 --fov 40
	case_run plugin-cylinder-cap-edge "$p/cylinder.txt" --plugin "$pl/cylinder.so" \
		--eye -50,-150,70 --look -50,20,70 --fov 30
	case_run plugin-torus "$p/torus.txt" --plugin "$pl/torus.so" --eye 0,-160,110 --look 0,20,25 --fov 60
	case_run plugin-torus-edge-on "$p/torus.txt" --plugin "$pl/torus.so" \
		--eye 50,-150,12 --look 50,30,12 --fov 40
	case_run plugin-torus-grazing "$p/torus.txt" --plugin "$pl/torus.so" \
		--eye 50,-150,34.5 --look 50,30,23.9 --fov 30
	if [ -f "$course/abir66-quad.txt" ]; then
		case_run course-abir66-quad "$course/abir66-quad.txt" --plugin "$pl/quad.so"
	else
		missing course-abir66-quad "$course/abir66-quad.txt is missing"
	fi
else
	missing plugins "$pl/*.so are not built (make plugins)"
fi

# The camera, checked by something other than scene2pov's export of it
# (which takes the camera from the same code as whitted, so that a camera
# turned upside down in both would still compare equal): four flat
# spheres, one per quadrant of the view, whose places follow by hand from
# scene-format.md's camera (see the scene file).  Each image must show
# each sphere in its quadrant: whitted's, POV-Ray's of the export, and
# POV-Ray's of a scene written here with a camera computed here from the
# contract; and whitted's must match that last one.  The second row turns
# the up vector over, which swaps the quadrants both ways.
camera_case "camera" "$root/tests/scenes/camera-quadrants.txt" 0 0,-200,10 0,0,0 0,0,1 80 \
	0,0,255 255,0,0 0,255,0 255,255,0
camera_case "camera-up-down" "$root/tests/scenes/camera-quadrants.txt" 0 0,-200,10 0,0,0 0,0,-1 80 \
	255,255,0 0,255,0 255,0,0 0,0,255
# The nearfar camera: the same quadrants in a nearfar file whose header
# makes FOVX = 1.8 x 50 = 90 degrees, with two spheres that only so wide a
# view shows (see the scene file); POV-Ray's camera written here widens
# right by the handout's rule, whitted's image must match it.
camera_case "camera-nearfar" "$root/tests/scenes/camera-quadrants-nearfar.txt" 1.8 \
	0,-200,10 0,0,0 0,0,1 50 \
	0,0,255 255,0,0 0,255,0 255,255,0

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

# scene2pov's .ini works from any directory: povray run from the parent
# (with a textured floor, whose image the .pov names) writes the PNG beside
# the .pov, the image (its pixels: POV-Ray's PNG has its own text) of the
# same run from its own directory.
rm -rf "$out/anywhere" && mkdir -p "$out/anywhere/sub" "$out/home"
"$build/scene2pov" -q -s 32 --floor-texture "$root/tests/textures/white.bmp" -o "$out/anywhere/sub/a.pov" \
	"$s/sphere.txt" >/dev/null &&
	(cd "$out/anywhere" && HOME="$out/home" povray sub/a.ini +WT2 -V >povray.log 2>&1) &&
	[ -s "$out/anywhere/sub/a.png" ] && mv "$out/anywhere/sub/a.png" "$out/anywhere/from-parent.png" &&
	(cd "$out/anywhere/sub" && HOME="$out/home" povray a.ini +WT2 -V >>../povray.log 2>&1) &&
	"$build/imgcmp" "$out/anywhere/sub/a.png" "$out/anywhere/from-parent.png" | grep -q '^psnr=inf .*max=0 '
if [ $? -eq 0 ]; then
	pass=$((pass + 1))
	printf '%-34s %s\n' "ini-from-anywhere" "ok"
else
	fail=$((fail + 1))
	failed="$failed ini-from-anywhere"
	printf '%-34s %s\n' "ini-from-anywhere" "FAIL (povray from the parent: $(tail -3 "$out/anywhere/povray.log"))"
fi

# Antialiasing, textured floors and glass (issue 14).
. "$root/tests/povcheck-features.sh"

[ "$fail" -eq 0 ] || echo "povcheck: failing:$failed"
echo "povcheck: $pass passed, $fail failed, 0 skipped"
[ "$fail" -eq 0 ]
