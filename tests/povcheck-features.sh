# shellcheck shell=sh disable=SC2154
# Sourced by tests/povcheck.sh: the cross-validations of issue 14's
# features, with its functions (case_run, gate, missing) and variables
# (size, out, build, pass, fail).

# samples_case NAME SCENE N [OPTIONS...]: whitted at size S with --samples N
# against POV-Ray at N*S (no antialiasing) reduced by N x N box averaging.
samples_case() {
	name=$1 scene=$2 n=$3
	shift 3
	case "$name" in *"$filter"*) ;; *) return 0 ;; esac
	w="$out/$name-whitted.png"
	log="$out/$name.log"
	if ! "$build/whitted" -q --clamp final -s "$size" --samples "$n" "$@" "$scene" -o "$w" >"$log" 2>&1 ||
	   ! "$build/scene2pov" -q -s $((size * n)) "$@" "$scene" -o "$out/$name.pov" >>"$log" 2>&1 ||
	   ! (cd "$out" && HOME="$out/home" povray "$name.ini" +WT2 -V >>"$log" 2>&1) ||
	   ! "$build/imgfilter" box "$n" "$out/$name.png" "$out/$name-box.png" >>"$log" 2>&1; then
		missing "$name" "whitted, scene2pov, povray or imgfilter failed (see $log)"
		return 0
	fi
	gate "$name" "$out/$name-box.png" "ok (POV-Ray at $((size * n)), box-reduced)"
}

s="$root/scenes"
samples_case samples2-scene "$s/scene.txt" 2
samples_case samples3-mirrors "$s/mirrors.txt" 3
samples_case samples4-quadric "$s/quadric.txt" 4
samples_case samples3-nearfar "$s/nearfar.txt" 3

# The textured floor (--floor-texture): the BMP of 24-bit rows bottom-up
# as the handouts ship them on the white cells and a PNG on the black ones,
# on the classic floor (seen from above, where the textures are large) and
# on nearfar's infinite one; and one texture alone.
t="$root/tests/textures"
case_run texture-classic-above "$s/scene.txt" --floor-texture "$t/white.bmp,$t/black.png" \
	--eye 30,-120,140 --look 0,0,0
case_run texture-classic "$s/shadows.txt" --floor-texture "$t/white.bmp,$t/black.png"
case_run texture-white-only "$s/mirrors.txt" --floor-texture "$t/white.png" --eye 0,-150,90
case_run texture-nearfar "$s/nearfar.txt" --floor-texture "$t/white.bmp,$t/black.png" \
	--eye 60,-260,140
case_run texture-pyramid "$s/pyramid.txt" --floor-texture ",$t/black.png" --eye 120,-180,160 \
	--look 0,20,20
# The other forms whitted reads, which scene2pov hands POV-Ray as the
# decoded texels (an opaque 24-bit PNG beside the .pov): an RGBA PNG
# (whitted ignores the alpha; POV-Ray would apply it), a 32-bit XRGB BMP
# and a top-down BMP (POV-Ray misreads the first and refuses the second).
case_run texture-rgba-xrgb "$s/scene.txt" --floor-texture "$t/white-rgba.png,$t/black-topdown.bmp" \
	--eye 30,-120,140 --look 0,0,0
case_run texture-xrgb "$s/scene.txt" --floor-texture "$t/white-xrgb.bmp" --eye 30,-120,140 \
	--look 0,0,0

# Glass (--glass INDEX:IOR:KT), with POV-Ray's interior ior and transmit
# (no Fresnel) and whitted's opaque shadows (the glass no_shadow, an unseen
# twin casting its shadow): glass spheres (in and out again, two of them
# with other indices), the nearfar file's glass cube at recursion 2 to 6
# (each level adds a passage; the cube's walls reflect totally inside,
# where both take the mirror ray whole) and a prism of the course's
# objects: a glass square pyramid (tests/scenes/glass-prism.txt).
case_run glass-sphere "$s/sphere.txt" -r 6 --glass 2:1.5:0.8
case_run glass-spheres-ior "$s/sphere.txt" -r 5 --glass 1:1.1:0.6,3:1.33:0.7 --eye 40,-150,60
case_run glass-sphere-nearfar "$s/nearfar.txt" -r 6 --glass 3:1.5:0.8
for r in 2 3 4 6; do
	case_run "glass-cube-r$r" "$s/nearfar.txt" -r "$r" --glass 1:1.5:0.8
done
case_run glass-prism "$root/tests/scenes/glass-prism.txt" -r 6 --glass 1:1.5:0.85
# Entering and leaving decided by the ray's glass stack, not the normal's
# sign: a sphere written as a quadric with its coefficients negated (its
# gradient points inwards), and glass nested in glass (eta 1.5 / 1.2).
case_run glass-quadric-negated "$root/tests/scenes/glass-quadric-negated.txt" -r 6 \
	--glass 1:1.5:0.8
case_run glass-nested "$root/tests/scenes/glass-nested.txt" -r 6 --glass 1:1.5:0.8,2:1.2:0.7
case_run glass-prism-above "$root/tests/scenes/glass-prism.txt" -r 6 --glass 1:1.6:0.8 \
	--eye 90,-170,150 --look 0,20,20
