#!/bin/sh
# Renders a scene with GNU parallel, on this machine or on others over ssh:
# the tiles of a COLUMNSxROWS grid, then merges them into one image, or the
# frames of an animation, one job each.  See docs/distributed.md.
#
# Usage:
#   scripts/render-parallel.sh --grid CxR -o FULL.png [OPTIONS] SCENE [-- WHITTED-OPTIONS]
#   scripts/render-parallel.sh --frames N -o 'DIR/frame-%04d.png' [OPTIONS] SCENE [-- WHITTED-OPTIONS]
# Options:
#   --sshlogin LOGIN   run jobs there (repeatable; ':' is this machine), as
#                      parallel's --sshlogin; ssh options come from PARALLEL_SSH
#   --jobs N           jobs at a time per machine (parallel's -j; default one
#                      per core)
#   --threads N        whitted threads per job (default 1)
#   --whitted PATH     the whitted program, the same path on every machine
#                      (default: WHITTED, else build/whitted beside this
#                      script, else whitted on PATH)
#   --tiles DIR        where the tiles go (default: FULL.tiles, removed after
#                      a successful merge unless --keep-tiles)
#   --keep-tiles
# Without --transfer every machine must see this directory's files at the
# same absolute paths (a shared file system).  With --transfer, parallel
# copies the scene to each machine and the tiles or frames back.
# WHITTED-OPTIONS (size, recursion, camera, floor, clamp, --path ...) go to
# every job; they must be the same for all, which merge checks.
# Exit status: 0 success, 1 a failed job or merge, 2 bad command line.
set -u

me=render-parallel
die_usage() { echo "$me: error: $*" >&2; echo "Usage: see the comment at the top of $0" >&2; exit 2; }
die() { echo "$me: error: $*" >&2; exit 1; }
abspath() { case "$1" in /*) printf '%s\n' "$1" ;; *) printf '%s/%s\n' "$(pwd)" "$1" ;; esac; }

grid="" frames="" output="" scene="" jobs="" threads=1 whitted="${WHITTED:-}" tiles=""
keep=0 transfer=0 sshlogins=""
nl='
'
while [ $# -gt 0 ]; do
	case "$1" in
	--grid) [ $# -ge 2 ] || die_usage "--grid needs a value"; grid=$2; shift 2 ;;
	--frames) [ $# -ge 2 ] || die_usage "--frames needs a value"; frames=$2; shift 2 ;;
	-o|--output) [ $# -ge 2 ] || die_usage "$1 needs a value"; output=$2; shift 2 ;;
	--sshlogin|-S) [ $# -ge 2 ] || die_usage "$1 needs a value"; sshlogins="$sshlogins$2$nl"; shift 2 ;;
	--jobs|-j) [ $# -ge 2 ] || die_usage "$1 needs a value"; jobs=$2; shift 2 ;;
	--threads) [ $# -ge 2 ] || die_usage "--threads needs a value"; threads=$2; shift 2 ;;
	--whitted) [ $# -ge 2 ] || die_usage "--whitted needs a value"; whitted=$2; shift 2 ;;
	--tiles) [ $# -ge 2 ] || die_usage "--tiles needs a value"; tiles=$2; shift 2 ;;
	--keep-tiles) keep=1; shift ;;
	--transfer) transfer=1; shift ;;
	-h|--help) sed -n '2,/^set -u/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
	--) shift; break ;;
	-*) die_usage "unknown option '$1'" ;;
	*) [ -z "$scene" ] || die_usage "one SCENE expected, found also '$1'"; scene=$1; shift ;;
	esac
done
[ -n "$scene" ] || die_usage "no SCENE given"
[ -f "$scene" ] || die "$scene: no such file"
[ -n "$output" ] || die_usage "no output given (-o)"
[ -n "$grid" ] || [ -n "$frames" ] || die_usage "give --grid CxR or --frames N"
[ -z "$grid" ] || [ -z "$frames" ] || die_usage "--grid and --frames cannot be combined"
command -v parallel >/dev/null 2>&1 || die "GNU parallel is not installed (apt-get install parallel)"
if [ -z "$whitted" ]; then
	here=$(cd "$(dirname "$0")" && pwd)
	if [ -x "$here/../build/whitted" ]; then whitted=$(cd "$here/.." && pwd)/build/whitted
	else whitted=whitted; fi
fi
case "$whitted" in */*) whitted=$(abspath "$whitted") ;; esac

# parallel's own options: machines and jobs per machine.
popts=""
[ -z "$jobs" ] || popts="-j$jobs"
sshfile=""
if [ -n "$sshlogins" ]; then
	sshfile=$(mktemp) || die "cannot make a temporary file"
	printf '%s' "$sshlogins" >"$sshfile"
fi
cleanup() { [ -z "$sshfile" ] || rm -f "$sshfile"; }
trap cleanup EXIT
trap 'exit 130' INT TERM
run_parallel() {
	# "$@": the command with {}; the job numbers come on standard input.
	if [ -n "$sshfile" ]; then
		parallel --halt now,fail=1 -q $popts --sshloginfile "$sshfile" "$@"
	else
		parallel --halt now,fail=1 -q $popts "$@"
	fi
}

if [ -n "$grid" ]; then
	case "$grid" in *[!0-9x]*|x*|*x|*x*x*|"") die_usage "--grid: expected COLUMNSxROWS, found '$grid'" ;; esac
	cols=${grid%x*} rows=${grid#*x}
	n=$((cols * rows))
	[ "$n" -ge 1 ] || die_usage "--grid: expected COLUMNSxROWS >= 1x1, found '$grid'"
	[ -n "$tiles" ] || tiles="${output%.*}.tiles"
	mkdir -p "$tiles" || die "cannot make $tiles"
	rm -f "$tiles"/tile-*.png
	if [ "$transfer" = 1 ]; then
		# Relative names: parallel recreates them under the remote
		# working directory and brings the tile back next to the scene.
		cp "$scene" "$tiles/scene.txt" || die "cannot copy $scene"
		( cd "$tiles" && seq 1 "$n" | run_parallel --wd ".whitted-render-$$" --basefile scene.txt \
			--return 'tile-{}.png' --cleanup \
			"$whitted" -q -j "$threads" "$@" --grid "$grid" --tile '{}' \
			-o 'tile-{}.png' scene.txt ) || die "a tile job failed"
		rm -f "$tiles/scene.txt"
	else
		scene_abs=$(abspath "$scene") tiles_abs=$(abspath "$tiles")
		seq 1 "$n" | run_parallel "$whitted" -q -j "$threads" "$@" --grid "$grid" --tile '{}' \
			-o "$tiles_abs/tile-{}.png" "$scene_abs" || die "a tile job failed"
	fi
	"$whitted" merge -o "$output" "$tiles"/tile-*.png || exit 1
	[ "$keep" = 1 ] || rm -rf "$tiles"
	echo "$me: wrote $output from $n tiles"
else
	case "$frames" in ''|*[!0-9]*) die_usage "--frames: expected a number, found '$frames'" ;; esac
	[ "$frames" -ge 1 ] || die_usage "--frames: expected a number >= 1"
	if [ -d "$output" ] || [ "${output%/}" != "$output" ]; then
		mkdir -p "$output" || die "cannot make $output"
		output="${output%/}/frame-%04d.png"
	fi
	case "$output" in *%*d*) ;; *) die_usage "-o: with --frames, give a pattern with %04d or a directory" ;; esac
	outdir=$(dirname "$output")
	mkdir -p "$outdir" || die "cannot make $outdir"
	if [ "$transfer" = 1 ]; then
		# Each job names its frame file plainly and parallel returns it.
		base=$(basename "$output")
		cp "$scene" "$outdir/.scene-$$.txt" || die "cannot copy $scene"
		( cd "$outdir" && seq 1 "$frames" | run_parallel --wd ".whitted-render-$$" --basefile ".scene-$$.txt" \
			--return "{=\$_=sprintf(q{$base},\$_)=}" --cleanup \
			"$whitted" -q -j "$threads" "$@" --frames "$frames" --frame '{}' \
			-o "$base" ".scene-$$.txt" ) || { rm -f "$outdir/.scene-$$.txt"; die "a frame job failed"; }
		rm -f "$outdir/.scene-$$.txt"
	else
		scene_abs=$(abspath "$scene") out_abs=$(abspath "$output")
		seq 1 "$frames" | run_parallel "$whitted" -q -j "$threads" "$@" --frames "$frames" \
			--frame '{}' -o "$out_abs" "$scene_abs" || die "a frame job failed"
	fi
	echo "$me: wrote $frames frames to $output"
fi
