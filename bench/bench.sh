#!/bin/sh
# The benchmark behind `make bench`: whitted against POV-Ray 3.7 on the
# course example at 1536x1536 and on generated scenes of small spheres and
# triangles at 512x512 (gen_scene: 1k, 100k and 1M covering the surfaces
# of six balls; 1k and 100k in a cloud, the hardest layout for any
# hierarchy), both with 2 threads, runs alternating between the two
# renderers; prints a Markdown table of medians and the growth from 1k to
# 100k.  It is a benchmark, not a test: it fails only when a program fails.
#
# Environment: RUNS (default 5; the 1M case does 3), THREADS (2),
# CASES (default "example gen-1k gen-100k gen-1M cloud-1k cloud-100k"),
# BENCH_DIR (build/bench-out), POV_1M=1 to time POV-Ray on 1M primitives too,
# POV_EXPORT (default build/scene2pov): the exporter, called as
# "$POV_EXPORT --finish plain -q -s SIZE -o OUT.pov SCENE"; it writes OUT.ini
# beside OUT.pov (size, no antialiasing, display off), and POV-Ray runs as
# "povray OUT.ini +IOUT.pov +WT2".
set -eu

BUILD=${BUILD:-build}
DIR=${BENCH_DIR:-$BUILD/bench-out}
RUNS=${RUNS:-5}
THREADS=${THREADS:-2}
WHITTED=$BUILD/whitted
GEN=$BUILD/gen_scene
POV_EXPORT=${POV_EXPORT:-$BUILD/scene2pov}
mkdir -p "$DIR"

have_pov=no
if command -v povray >/dev/null 2>&1 && [ -x "$POV_EXPORT" ]; then
	have_pov=yes
fi

# The generated scenes are made once and kept (the 1M file is 100 MB),
# until the generator changes.
gen() {
	f=$DIR/$1-$2.txt
	if [ ! -s "$f" ] || [ "$GEN" -nt "$f" ]; then
		"$GEN" --layout "$1" "$2" >"$f.tmp" && mv "$f.tmp" "$f"
	fi
}
for n in 1 1000 100000 1000000; do
	gen surface $n
done
gen cloud 1000
gen cloud 100000

now() { date +%s.%N; }

# run_timed OUT_PREFIX CMD...: wall seconds into OUT_PREFIX.t, peak KiB into
# OUT_PREFIX.m, stderr into OUT_PREFIX.err.
run_timed() {
	rt_out=$1
	shift
	rt_t0=$(now)
	/usr/bin/time -f %M -o "$rt_out.m" "$@" 2>"$rt_out.err" >/dev/null ||
		{ echo "bench: failed: $*" >&2; cat "$rt_out.err" >&2; exit 1; }
	rt_t1=$(now)
	echo "$rt_t1 - $rt_t0" | bc -l >"$rt_out.t"
}

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

# Rays traced, from whitted's --stats line "rays: A primary, B shadow, C reflection, ...".
rays_of() { sed -n 's/^rays: *\([0-9]*\) primary, \([0-9]*\) shadow, \([0-9]*\) reflection.*/\1 \2 \3/p' "$1" | awk '{ print $1 + $2 + $3 }'; }
render_time_of() { sed -n 's/.*render \([0-9.]*\) s.*/\1/p' "$1"; }

# The memory of a one-object scene at the same size: what every run needs
# (program, libraries, image buffer), subtracted for bytes per primitive.
base_kib() {
	run_timed "$DIR/base$1" "$WHITTED" -q -j "$THREADS" -s "$1" -o "$DIR/base.ppm" "$DIR/surface-1.txt"
	cat "$DIR/base$1.m"
}

# bench NAME SCENE SIZE PRIMITIVES RUNS POV(yes/no)
bench() {
	name=$1 scene=$2 size=$3 prims=$4 runs=$5 pov=$6
	w="$DIR/$name.w" p="$DIR/$name.p"
	rm -f "$w".times "$p".times "$w".mems "$w".rps
	if [ "$pov" = yes ]; then
		"$POV_EXPORT" --finish plain -q -s "$size" -o "$DIR/$name.pov" "$scene"
	fi
	i=0
	while [ $i -lt "$runs" ]; do
		run_timed "$w" "$WHITTED" -q --stats --progress never -j "$THREADS" -s "$size" \
			-o "$DIR/$name.png" "$scene"
		cat "$w.t" >>"$w.times"
		cat "$w.m" >>"$w.mems"
		echo "$(rays_of "$w.err") / $(render_time_of "$w.err") / 1000000" | bc -l >>"$w.rps"
		if [ "$pov" = yes ]; then
			run_timed "$p" povray "$DIR/$name.ini" +I"$DIR/$name.pov" +O"$DIR/$name.pov.png" \
				+WT"$THREADS" -V -GA
			cat "$p.t" >>"$p.times"
		fi
		i=$((i + 1))
	done
	wt=$(median <"$w.times")
	mem=$(median <"$w.mems")
	rps=$(median <"$w.rps")
	base=$(base_kib "$size")
	if [ "$prims" -gt 1 ]; then
		bpp=$(echo "($mem - $base) * 1024 / $prims" | bc)
	else
		bpp="-"
	fi
	if [ "$pov" = yes ]; then
		pt=$(median <"$p.times")
		echo "$pt" >"$DIR/$name.pmedian"
		ratio=$(printf '%.1f' "$(echo "$pt / $wt" | bc -l)")
		pt=$(printf '%.3f' "$pt")
	else
		pt="not run" ratio="-"
	fi
	printf '| %s | %s | %s | %.3f | %s | %s | %.1f | %.1f | %s |\n' "$name" "$size" "$runs" \
		"$wt" "$pt" "$ratio" "$rps" "$(echo "$mem / 1024" | bc -l)" "$bpp"
	echo "$wt" >"$DIR/$name.median"
	rm -f "$DIR/$name.png" "$DIR/$name.pov.png"
}

# How much of the machine is free: two busy threads take as long as one
# when another program holds a core.
spin_cpus() {
	rt_t0=$(now)
	"$WHITTED" -q -j 2 -s 768 -o "$DIR/spin.ppm" scenes/scene.txt
	rt_t1=$(now)
	"$WHITTED" -q -j 1 -s 768 -o "$DIR/spin.ppm" scenes/scene.txt
	rt_t2=$(now)
	printf '%.1f' "$(echo "($rt_t2 - $rt_t1) / ($rt_t1 - $rt_t0)" | bc -l)"
}

echo "machine: load average $(cut -d' ' -f1-3 /proc/loadavg) before the run; whitted -j2 runs $(spin_cpus)x as fast as -j1"
echo "whitted $("$WHITTED" --version | cut -d' ' -f2), $(nproc) cores ($(sed -n 's/^model name[^:]*: //p' /proc/cpuinfo | head -1)), $THREADS threads each; POV-Ray: $( [ $have_pov = yes ] && povray --version 2>&1 | sed -n 's/^POV-Ray \([0-9.]*\).*/\1/p' | head -1 || echo "not run ($POV_EXPORT or povray missing)")"
echo
echo "| scene | size | runs | whitted s (median) | POV-Ray s (median) | POV/whitted | whitted M rays/s (render) | peak MiB | bytes/primitive beyond a 1-object scene |"
echo "|---|---|---|---|---|---|---|---|---|"
pov1m=no
[ "${POV_1M:-0}" = 1 ] && pov1m=$have_pov
runs1m=$RUNS
[ "$runs1m" -gt 3 ] && runs1m=3
rm -f "$DIR"/*.median "$DIR"/*.pmedian
for c in ${CASES:-example gen-1k gen-100k gen-1M cloud-1k cloud-100k}; do
	case $c in
	example) bench example scenes/scene.txt 1536 1 "$RUNS" "$have_pov" ;;
	gen-1k) bench gen-1k "$DIR/surface-1000.txt" 512 1000 "$RUNS" "$have_pov" ;;
	gen-100k) bench gen-100k "$DIR/surface-100000.txt" 512 100000 "$RUNS" "$have_pov" ;;
	gen-1M) bench gen-1M "$DIR/surface-1000000.txt" 512 1000000 "$runs1m" "$pov1m" ;;
	cloud-1k) bench cloud-1k "$DIR/cloud-1000.txt" 512 1000 "$RUNS" "$have_pov" ;;
	cloud-100k) bench cloud-100k "$DIR/cloud-100000.txt" 512 100000 "$RUNS" "$have_pov" ;;
	*) echo "bench: unknown case '$c'" >&2; exit 2 ;;
	esac
done
echo
# growth LAYOUT NAME: the 1k -> 100k time ratios of whitted and POV-Ray.
growth() {
	if [ -s "$DIR/$1-100k.median" ] && [ -s "$DIR/$1-1k.median" ]; then
		g="whitted 1k -> 100k ($2): $(printf '%.2f' "$(echo "$(cat "$DIR/$1-100k.median") / $(cat "$DIR/$1-1k.median")" | bc -l)")x the time"
		if [ -s "$DIR/$1-100k.pmedian" ] && [ -s "$DIR/$1-1k.pmedian" ]; then
			g="$g (POV-Ray: $(printf '%.2f' "$(echo "$(cat "$DIR/$1-100k.pmedian") / $(cat "$DIR/$1-1k.pmedian")" | bc -l)")x)"
		fi
		echo "$g"
	fi
}
growth gen "surface"
growth cloud "cloud"
[ "$pov1m" = yes ] || echo "POV-Ray is not timed on 1M primitives (POV_1M=1 to do so)."
