#!/bin/sh
# imgcmp's own tests: the gate passes identical images (in any of the three
# formats, and a PNG whose gAMA chunk would change the samples if it were
# honoured) and fails images that really differ: a half-pixel camera shift,
# a wrong gamma, a different size, a pixel far off; its options and exit
# statuses.  Needs no POV-Ray.
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
build="$root/build"
tmp="$build/imgcmp-test"
pass=0 fail=0

rm -rf "$tmp"
mkdir -p "$tmp" || exit 1

ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "imgcmptest: FAIL: $*"; }

# expect STATUS DESCRIPTION imgcmp-args...
expect() {
	want=$1 what=$2
	shift 2
	"$build/imgcmp" "$@" >"$tmp/out" 2>"$tmp/err"
	got=$?
	if [ "$got" -eq "$want" ]; then ok; else bad "$what: exit $got, expected $want"; cat "$tmp/out" "$tmp/err"; fi
}

w="$build/whitted -q -s 128"
$w "$root/scenes/scene.txt" -o "$tmp/a.png" &&
$w "$root/scenes/scene.txt" -o "$tmp/a.ppm" &&
$w "$root/scenes/scene.txt" -o "$tmp/a.bmp" &&
# Half a pixel to the right: the pixel is 2 tan(40 deg) 200.25 / 128 wide
# at the look-at point; eye and look-at move by half of that.
$w --eye 1.3136,-200,10 --look 1.3136,0,0 "$root/scenes/scene.txt" -o "$tmp/shift.png" &&
"$build/imgfilter" gamma 2.2 "$tmp/a.png" "$tmp/gamma.png" &&
"$build/imgfilter" gama1 "$tmp/a.png" "$tmp/gama1.png" &&
"$build/imgfilter" poke 5 7 3 "$tmp/a.png" "$tmp/poke3.png" &&
"$build/imgfilter" poke 5 7 20 "$tmp/a.png" "$tmp/poke20.png" &&
$w -s 127 "$root/scenes/scene.txt" -o "$tmp/small.png" || { echo "imgcmptest: could not make the test images"; exit 1; }

expect 0 "identical PNGs" "$tmp/a.png" "$tmp/a.png"
grep -q '^psnr=inf mean=0.0000 max=0 off2=0.0000% off8=0.0000% PASS$' "$tmp/out" && ok ||
	bad "identical PNGs: expected psnr=inf and zero errors, got $(cat "$tmp/out")"
expect 0 "PNG vs PPM of one render" "$tmp/a.png" "$tmp/a.ppm"
expect 0 "PNG vs BMP of one render" "$tmp/a.png" "$tmp/a.bmp"
expect 0 "a gAMA 1.0 chunk must not change the samples" "$tmp/a.png" "$tmp/gama1.png"
grep -q 'max=0 ' "$tmp/out" && ok || bad "gAMA 1.0: samples changed: $(cat "$tmp/out")"

expect 1 "a half-pixel camera shift" "$tmp/a.png" "$tmp/shift.png"
[ -f "$tmp/shift-diff.png" ] && ok || bad "half-pixel shift: no difference image written"
grep -q "shift-diff.png" "$tmp/err" && ok || bad "half-pixel shift: the message does not say where the difference image is"
grep -q "worst pixel (" "$tmp/err" && ok || bad "half-pixel shift: the message does not locate the worst pixel"
expect 1 "a wrong gamma (2.2 encoding)" "$tmp/a.png" "$tmp/gamma.png"
expect 1 "different sizes" "$tmp/a.png" "$tmp/small.png"

# One pixel of 16384 is 0.006%: within the >2 budget (0.2%), over none of
# the >8 budget (0.02%); a PSNR gate above its 89 dB fails it.
expect 0 "one pixel off by 3" "$tmp/a.png" "$tmp/poke3.png"
expect 1 "one pixel off by 3, --min-psnr 100" --min-psnr 100 "$tmp/a.png" "$tmp/poke3.png"
expect 1 "one pixel off by 3, --max-off2 0" --max-off2 0 "$tmp/a.png" "$tmp/poke3.png"
expect 0 "one pixel off by 20, within the default >8 budget (64 dB)" "$tmp/a.png" "$tmp/poke20.png"
grep -q 'max=20 ' "$tmp/out" && ok || bad "one pixel off by 20: max error not 20: $(cat "$tmp/out")"
expect 1 "one pixel off by 20, --max-off8 0" --max-off8 0 "$tmp/a.png" "$tmp/poke20.png"
grep -q "(5,7) off by 20" "$tmp/err" && ok || bad "the worst pixel is not located at (5,7): $(cat "$tmp/err")"

expect 0 "--diff on a pass writes the image" --diff "$tmp/d.png" "$tmp/a.png" "$tmp/poke20.png"
[ -f "$tmp/d.png" ] && ok || bad "--diff did not write $tmp/d.png"
expect 1 "a file that is not an image" "$tmp/a.png" "$root/scenes/scene.txt"
expect 1 "a missing file" "$tmp/a.png" "$tmp/missing.png"
expect 2 "one image" "$tmp/a.png"
expect 2 "an unknown option" --frobnicate "$tmp/a.png" "$tmp/a.png"
expect 2 "a bad gate value" --min-psnr abc "$tmp/a.png" "$tmp/a.png"
expect 0 "--help" --help

echo "imgcmptest: $pass passed, $fail failed, 0 skipped"
[ "$fail" -eq 0 ]
