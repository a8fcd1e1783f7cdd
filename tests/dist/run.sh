#!/bin/sh
# End-to-end tests of region renders, the merge, frames and the scripts
# that distribute them (GNU parallel locally and over ssh to localhost, the
# Slurm array script run by hand).  Ends with "dist: N passed, N failed,
# N skipped"; a check whose tools are not installed is reported NOT RUN and
# counted as skipped, never as passed; one whose tools are installed but
# that could not run (sshd refusing) fails.
set -u
top=$(cd "$(dirname "$0")/../.." && pwd)
W=$top/build/whitted
tmp=$(mktemp -d)
sshd_pid=""
cleanup() {
	[ -z "$sshd_pid" ] || kill "$sshd_pid" 2>/dev/null
	rm -rf "$tmp"
}
trap cleanup EXIT
pass=0 fail=0 skipped=0 why=""
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }
check() { name=$1; shift; if "$@"; then ok; else bad "$name"; fi; }
# not_run N WHY: N checks that cannot run here.
not_run() {
	echo "NOT RUN: $1 checks: $2"
	skipped=$((skipped + $1))
	why="${why:-: }${why:+; }$2"
}
cd "$tmp" || exit 1
cp "$top/scenes/scene.txt" scene.txt
printf '%s\n' 2 9 1 sphere 0 0 10 10 1 0 0 0.4 0.2 0.2 0.2 1 1 -50 50 50 1 1 1 >other.txt

# expect_fail NAME STATUS OUTPUT GREP COMMAND...: the command exits with
# STATUS, says GREP on stderr and leaves no file OUTPUT.
expect_fail() {
	name=$1 want=$2 out=$3 msg=$4
	shift 4
	"$@" >/dev/null 2>err.txt
	st=$?
	if [ "$st" != "$want" ]; then bad "$name: exit $st, expected $want: $(cat err.txt)"; return; fi
	if ! grep -q -- "$msg" err.txt; then bad "$name: message '$(cat err.txt)' lacks '$msg'"; return; fi
	if [ -e "$out" ]; then bad "$name: left $out behind"; rm -f "$out"; return; fi
	ok
}

# split SIZE COLS ROWS: prints X0,Y0,X1,Y1 of each region of an even grid.
split() {
	awk -v s="$1" -v c="$2" -v r="$3" 'BEGIN { for (j = 0; j < r; j++) for (i = 0; i < c; i++)
		printf "%d,%d,%d,%d\n", int(i*s/c), int(j*s/r), int((i+1)*s/c), int((j+1)*s/r) }'
}

# Region renders merged equal the single render, file and pixels, for
# several splits and odd sizes.
for size in 23 37; do
	"$W" -q -s "$size" -o "full$size.png" scene.txt && "$W" -q -s "$size" -o "full$size.ppm" scene.txt ||
		bad "single render $size"
	for grid in 1x1 2x2 3x5 5x3; do
		rm -rf t && mkdir t
		n=0
		for r in $(split "$size" "${grid%x*}" "${grid#*x}"); do
			n=$((n + 1))
			"$W" -q -s "$size" --region "$r" -o "t/$n.png" scene.txt || bad "region $r of $size"
		done
		"$W" merge -o m.png t/*.png && cmp -s m.png "full$size.png"
		check "merge $grid of $size equals the single render (PNG bytes)" [ $? = 0 ]
		"$W" merge -o m.ppm t/*.png && cmp -s m.ppm "full$size.ppm"
		check "merge $grid of $size equals the single render (pixels)" [ $? = 0 ]
		# --grid cuts the same way.
		rm -rf g && mkdir g
		k=1
		while [ "$k" -le "$n" ]; do
			"$W" -q -s "$size" --grid "$grid" --tile "$k" -o "g/$k.png" scene.txt || bad "--grid $grid --tile $k"
			k=$((k + 1))
		done
		"$W" merge -o mg.png g/*.png && cmp -s mg.png "full$size.png"
		check "--grid $grid tiles of $size merge to the single render" [ $? = 0 ]
		rm -f m.png m.ppm mg.png
	done
done

# A tile is the region's size and records its place.
"$W" -q -s 37 --region 10,20,30,25 -o tile.png scene.txt
check "tile: exit 0" [ $? = 0 ]
check "tile: PNG IHDR is 20x5" [ "$(od -An -tx1 -j16 -N8 tile.png | tr -d ' \n')" = "0000001400000005" ]
off=$(grep -abo oFFs tile.png | head -n1 | cut -d: -f1)
check "tile: oFFs chunk is (10,20) pixels" \
	[ "$(od -An -tx1 -j$((off + 4)) -N9 tile.png 2>/dev/null | tr -d ' \n')" = "0000000a0000001400" ]
check "tile: whitted-tile text has the full size" grep -aq "full-size 37 37" tile.png
check "tile: whitted-tile text has the region" grep -aq "region 10 20 30 25" tile.png
check "tile: whitted-tile text has the options" grep -aq "options size=37 recursion=4 eye=0,-200,10" tile.png
"$W" -q -s 37 --region 0,0,5,5 scene.txt
check "tile: default name" [ -f scene-region-0-0-5-5.png ]

# Bad regions are command-line errors with no output.
expect_fail "region empty" 2 r.png "empty" "$W" -q -s 37 --region 5,5,5,9 -o r.png scene.txt
expect_fail "region inverted" 2 r.png "inverted" "$W" -q -s 37 --region 9,5,5,9 -o r.png scene.txt
expect_fail "region outside" 2 r.png "outside the 37x37" "$W" -q -s 37 --region 0,0,38,9 -o r.png scene.txt
expect_fail "region outside (file size)" 2 r.png "outside the 768x768" "$W" -q --region 0,0,769,9 -o r.png scene.txt
expect_fail "region negative" 2 r.png "X0,Y0,X1,Y1" "$W" -q -s 37 --region -1,0,5,5 -o r.png scene.txt
expect_fail "region three numbers" 2 r.png "X0,Y0,X1,Y1" "$W" -q -s 37 --region 0,0,5 -o r.png scene.txt
expect_fail "region junk" 2 r.png "X0,Y0,X1,Y1" "$W" -q -s 37 --region 0,0,5,5x -o r.png scene.txt
expect_fail "region as BMP" 2 r.bmp "tiles are PNG" "$W" -q -s 37 --region 0,0,5,5 -o r.bmp scene.txt
expect_fail "region --format ppm" 2 r.png "tiles are PNG" "$W" -q -s 37 --region 0,0,5,5 --format ppm -o r.png scene.txt
expect_fail "grid without tile" 2 r.png "needs --tile" "$W" -q -s 37 --grid 2x2 -o r.png scene.txt
expect_fail "tile past grid" 2 r.png "past the last tile" "$W" -q -s 37 --grid 2x2 --tile 5 -o r.png scene.txt
expect_fail "grid finer than image" 2 r.png "finer than" "$W" -q -s 3 --grid 4x1 --tile 1 -o r.png scene.txt
expect_fail "grid and region" 2 r.png "cannot be combined" "$W" -q -s 37 --grid 2x2 --tile 1 --region 0,0,1,1 -o r.png scene.txt

# The merge refuses bad sets of tiles with a clear error and no output.
rm -rf t && mkdir t
for r in $(split 37 2 2); do "$W" -q -s 37 --region "$r" -o "t/$r.png" scene.txt; done
set -- t/0,0,18,18.png t/18,0,37,18.png t/0,18,18,37.png t/18,18,37,37.png
"$W" merge -o good.png "$@"
check "merge of four tiles" cmp -s good.png full37.png
expect_fail "merge missing" 1 out.png "missing tile: no tile covers region 18,18,37,37" "$W" merge -o out.png "$1" "$2" "$3"
"$W" -q -s 37 --region 10,10,20,20 -o t/mid.png scene.txt
expect_fail "merge overlapping" 1 out.png "overlaps .* in region 10,10,18,18" "$W" merge -o out.png "$@" t/mid.png
expect_fail "merge same tile twice" 1 out.png "given twice" "$W" merge -o out.png "$@" "$1"
"$W" -q -s 37 --region 0,0,18,18 -o t/other-scene.png other.txt
expect_fail "merge foreign scene" 1 out.png "another scene file" "$W" merge -o out.png t/other-scene.png "$2" "$3" "$4"
sed 's/^4$/4 /' scene.txt >scene-space.txt
"$W" -q -s 37 --region 0,0,18,18 -o t/other-bytes.png scene-space.txt
expect_fail "merge scene differing by one byte" 1 out.png "another scene file" "$W" merge -o out.png "$2" t/other-bytes.png "$3" "$4"
"$W" -q -s 38 --region 0,0,18,18 -o t/other-size.png scene.txt
expect_fail "merge foreign full size" 1 out.png "38x38 image" "$W" merge -o out.png "$2" "$3" "$4" t/other-size.png
for opt in "-r 2" "--eye 0,-201,10" "--look 0,0,1" "--up 0,0.1,1" "--fov 70" "--floor 500,20" "--no-floor" "--clamp final"; do
	# shellcheck disable=SC2086
	"$W" -q -s 37 $opt --region 0,0,18,18 -o t/opt.png scene.txt
	expect_fail "merge foreign option $opt" 1 out.png "other options" "$W" merge -o out.png t/opt.png "$2" "$3" "$4"
done
"$W" -q -s 37 -j 1 --region 0,0,18,18 -o t/threads.png scene.txt
"$W" merge -o out.png t/threads.png "$2" "$3" "$4"
check "merge: --threads does not make a tile foreign" cmp -s out.png full37.png
rm -f out.png
expect_fail "merge a plain PNG" 1 out.png "not a whitted tile" "$W" merge -o out.png full37.png "$2" "$3" "$4"
expect_fail "merge a text file" 1 out.png "not a PNG file" "$W" merge -o out.png scene.txt "$2" "$3" "$4"
expect_fail "merge a missing file" 1 out.png "cannot open" "$W" merge -o out.png t/nothere.png "$2" "$3" "$4"
expect_fail "merge a directory" 1 out.png "is a directory, not a tile" "$W" merge -o out.png t "$2" "$3" "$4"
head -c 60 "$1" >t/short.png
expect_fail "merge a truncated tile" 1 out.png "truncated PNG" "$W" merge -o out.png t/short.png "$2" "$3" "$4"
sz=$(wc -c <"$1")
head -c $((sz - 40)) "$1" >t/cut.png
expect_fail "merge a tile cut in its image data" 1 out.png "$1\|t/cut.png" "$W" merge -o out.png t/cut.png "$2" "$3" "$4"
sed 's/region 0 0 18 18/region 0 0 18 19/' "$1" >t/edited.png
expect_fail "merge a tile with an edited chunk" 1 out.png "bad CRC" "$W" merge -o out.png t/edited.png "$2" "$3" "$4"
# Hostile tiles (tests/tools/hostile_png.py on tile 1): junk after IEND,
# image data that inflates to 16 MiB more than the tile's rows, a header
# claiming 16384x16384 in a small file, a damaged CRC in the image data:
# each refused at once, in little memory (ulimit -v: a fraction of what
# inflating them took) and time.
python3 "$top/tests/tools/hostile_png.py" hostile "$1" >/dev/null
for c in "tile-junk:junk after the end of the PNG (19 bytes after its IEND chunk)" \
	"tile-bomb:too much image data: the header's 18x18 needs 990 bytes, the data inflates to more" \
	"tile-claims:the header's 16384x16384 needs 805322752 bytes of image data, more than its" \
	"tile-bad-crc:damaged PNG file (bad CRC in its IDAT chunk)"; do
	f=${c%%:*} m=${c#*:}
	expect_fail "merge $f" 1 out.png "$m" sh -c 'ulimit -v 262144; exec timeout 10 "$@"' sh \
		"$W" merge -o out.png "hostile/$f.png" "$2" "$3" "$4"
done
echo keep >out.png
"$W" merge -o out.png "$1" "$2" "$3" 2>/dev/null
check "merge failure leaves an existing output alone" [ "$(cat out.png)" = keep ]
rm -f out.png
expect_fail "merge without -o" 2 out.png "no output" "$W" merge "$@"
expect_fail "merge without tiles" 2 out.png "no tiles" "$W" merge -o out.png
expect_fail "merge unknown format" 2 out.xyz "cannot tell the format" "$W" merge -o out.xyz "$@"
expect_fail "merge to a missing directory" 1 nodir/out.png "cannot write" "$W" merge -o nodir/out.png "$@"
ls -a | grep -q '^\.out\.png\.' && bad "merge left a temporary file" || ok

# Frames: an orbit and keyframes.
"$W" -q -s 24 -o still.png scene.txt
mkdir fr
"$W" -q -s 24 --frames 4 -o fr scene.txt
check "frames: four files in a directory" [ "$(ls fr | tr '\n' ' ')" = "frame-0001.png frame-0002.png frame-0003.png frame-0004.png " ]
check "frames: frame 1 is the still image" cmp -s fr/frame-0001.png still.png
"$W" -q -s 24 --frames 4 --frame 3 -o f3.png scene.txt
check "frames: --frame 3 equals the third frame of the whole run" cmp -s f3.png fr/frame-0003.png
"$W" -q -s 24 --frames 4 --frame 3 -o 'pat-%02d.png' scene.txt
check "frames: pattern %02d" cmp -s pat-03.png fr/frame-0003.png
check "frames: frames differ" sh -c "! cmp -s fr/frame-0001.png fr/frame-0003.png"
"$W" -q -s 24 -o half.ppm --eye 0,200,10 scene.txt
"$W" -q -s 24 --frames 4 --frame 3 -o f3.ppm scene.txt
nd=$(cmp -l f3.ppm half.ppm | wc -l)
check "frames: orbit frame 3 of 4 looks from the opposite side (eye 0,200,10; $nd bytes differ)" [ "$nd" -lt 20 ]
mkdir dfr
(cd dfr && "$W" -q -s 24 --frames 2 ../scene.txt)
check "frames: default names frame-%04d.png" [ "$(ls dfr | tr '\n' ' ')" = "frame-0001.png frame-0002.png " ]
printf '# a keyframe path\neye 0,-200,10\n\n  eye 0,-100,50 fov 60   # closer\n' >path.txt
"$W" -q -s 24 --frames 3 --path path.txt -o 'p%d.png' scene.txt
check "path: frame 1 is the first keyframe" cmp -s p1.png still.png
"$W" -q -s 24 --eye 0,-100,50 --fov 60 -o key2.png scene.txt
check "path: frame 3 is the last keyframe" cmp -s p3.png key2.png
"$W" -q -s 24 --eye 0,-150,30 --fov 70 -o mid.png scene.txt
check "path: frame 2 is interpolated halfway" cmp -s p2.png mid.png
printf 'eye 0,-200,10\nlook 1,2\n' >badpath.txt
expect_fail "path: a bad line" 1 q1.png "badpath.txt:2: error: look" "$W" -q -s 24 --frames 2 --path badpath.txt -o 'q%d.png' scene.txt
printf 'eye 0,-200,10\neye 0,0,0\n' >badcam.txt
expect_fail "path: a bad camera, no frame written" 1 q1.png "frame 2: the eye is at the look-at point" "$W" -q -s 24 --frames 2 --path badcam.txt -o 'q%d.png' scene.txt
expect_fail "path: missing file" 1 q1.png "cannot open" "$W" -q -s 24 --frames 2 --path nothere.txt -o 'q%d.png' scene.txt
expect_fail "frames: plain output name" 2 x.png "pattern with %04d" "$W" -q -s 24 --frames 3 -o x.png scene.txt
expect_fail "frames: bad pattern" 2 x.png "%d or %0Wd" "$W" -q -s 24 --frames 3 -o 'x%s.png' scene.txt
expect_fail "frames: two numbers" 2 x.png "more than one" "$W" -q -s 24 --frames 3 -o 'x%d%d.png' scene.txt
expect_fail "frame without frames" 2 x.png "needs --frames" "$W" -q -s 24 --frame 1 -o x.png scene.txt
expect_fail "frame past the end" 2 x.png "past the last frame" "$W" -q -s 24 --frames 3 --frame 4 -o x.png scene.txt
expect_fail "path without frames" 2 x.png "needs --frames" "$W" -q -s 24 --path path.txt -o x.png scene.txt
# Frames and regions together: the tiles of frame 2 merge to frame 2.
rm -rf t && mkdir t
for k in 1 2 3 4; do "$W" -q -s 24 --frames 4 --frame 2 --grid 2x2 --tile $k -o "t/$k.png" scene.txt; done
"$W" merge -o f2.png t/*.png
check "frames with regions: tiles of frame 2 merge to frame 2" cmp -s f2.png fr/frame-0002.png
"$W" -q -s 24 --frames 4 --frame 3 --grid 2x2 --tile 1 -o t/1.png scene.txt
expect_fail "frames with regions: a tile of another frame is foreign" 1 f.png "other options" "$W" merge -o f.png t/*.png

# GNU parallel, on this machine: the acceptance test (a 4x4 split).
if command -v parallel >/dev/null 2>&1; then
	"$W" -q -s 45 -o single45.png scene.txt
	"$top/scripts/render-parallel.sh" --grid 4x4 -o par.png scene.txt -- -s 45 >/dev/null
	check "parallel: exit 0" [ $? = 0 ]
	check "parallel: a 4x4 split merged equals the single render byte for byte" cmp -s par.png single45.png
	check "parallel: tiles removed" [ ! -e par.tiles ]
	mkdir pfr
	"$top/scripts/render-parallel.sh" --frames 4 -o pfr/ scene.txt -- -s 24 >/dev/null
	check "parallel: frames equal the sequential run" diff -r pfr fr
	"$top/scripts/render-parallel.sh" --grid 2x2 -o fails.png nothere.txt -- -s 24 >/dev/null 2>&1
	check "parallel: missing scene is an error" [ $? = 1 ]
	"$top/scripts/render-parallel.sh" --grid 2x2 -o fails.png scene.txt -- -s 24 --bogus >/dev/null 2>&1
	check "parallel: a failing job fails the run, no output" [ $? = 1 ] && [ ! -e fails.png ]
else
	not_run 6 "GNU parallel is not installed"
fi

# GNU parallel over ssh to localhost, with a private sshd and a fresh key.
start_sshd() {
	sshd=$(command -v sshd || echo /usr/sbin/sshd)
	[ -x "$sshd" ] && command -v ssh >/dev/null && command -v ssh-keygen >/dev/null || return 1
	mkdir -p "$tmp/ssh" && chmod 700 "$tmp/ssh"
	ssh-keygen -q -t ed25519 -N '' -f "$tmp/ssh/host" && ssh-keygen -q -t ed25519 -N '' -f "$tmp/ssh/id" || return 1
	cp "$tmp/ssh/id.pub" "$tmp/ssh/authorized_keys"
	[ "$(id -u)" != 0 ] || mkdir -p /run/sshd
	port=$((20000 + $$ % 20000))
	cat >"$tmp/ssh/config" <<-END
	Port $port
	ListenAddress 127.0.0.1
	HostKey $tmp/ssh/host
	AuthorizedKeysFile $tmp/ssh/authorized_keys
	PasswordAuthentication no
	KbdInteractiveAuthentication no
	PubkeyAuthentication yes
	PermitRootLogin prohibit-password
	StrictModes no
	UsePAM no
	PidFile $tmp/ssh/sshd.pid
	END
	"$sshd" -f "$tmp/ssh/config" -D -e 2>"$tmp/ssh/log" &
	sshd_pid=$!
	PARALLEL_SSH="ssh -p $port -i $tmp/ssh/id -o StrictHostKeyChecking=no -o UserKnownHostsFile=/dev/null -o BatchMode=yes -o LogLevel=ERROR"
	export PARALLEL_SSH
	tries=0
	while [ $tries -lt 50 ]; do
		$PARALLEL_SSH "$(id -un)@127.0.0.1" true 2>/dev/null && return 0
		sleep 0.1
		tries=$((tries + 1))
	done
	return 1
}
ssh_tools() {
	command -v parallel >/dev/null 2>&1 && command -v ssh >/dev/null && command -v ssh-keygen >/dev/null &&
		[ -x "$(command -v sshd || echo /usr/sbin/sshd)" ]
}
if ssh_tools && start_sshd; then
	login="2/$(id -un)@127.0.0.1"
	"$top/scripts/render-parallel.sh" --grid 4x4 --sshlogin "$login" -o ssh.png scene.txt -- -s 45 >/dev/null
	check "ssh: a 4x4 split over ssh to localhost equals the single render" cmp -s ssh.png single45.png
	"$top/scripts/render-parallel.sh" --transfer --grid 3x2 --sshlogin "$login" -o sshx.png scene.txt -- -s 45 >/dev/null
	check "ssh --transfer: 3x2 tiles copied back equal the single render" cmp -s sshx.png single45.png
	mkdir sfr
	"$top/scripts/render-parallel.sh" --transfer --frames 4 --sshlogin "$login" -o sfr/ scene.txt -- -s 24 >/dev/null
	check "ssh --transfer: frames equal the sequential run" diff -r sfr fr
else
	if ssh_tools; then
		# Everything is installed: the part could run, so its not
		# running is a failure.
		echo "FAIL: ssh to localhost: sshd did not start or let us in (see its log)"
		fail=$((fail + 1))
	else
		not_run 3 "ssh to localhost (no parallel, sshd or ssh)"
	fi
	[ ! -f "$tmp/ssh/log" ] || sed 's/^/  sshd: /' "$tmp/ssh/log" | head -n 5
fi
[ -z "$sshd_pid" ] || { kill "$sshd_pid" 2>/dev/null; wait "$sshd_pid" 2>/dev/null; sshd_pid=""; }
unset PARALLEL_SSH

# The Slurm script, with the array variables set by hand for every task.
mkdir sl
export WHITTED="$W"
for id in $(seq 0 15); do
	SLURM_ARRAY_TASK_ID=$id SLURM_ARRAY_TASK_MIN=0 SLURM_ARRAY_TASK_MAX=15 SLURM_ARRAY_TASK_COUNT=16 \
		SLURM_ARRAY_JOB_ID=42 SLURM_CPUS_PER_TASK=1 \
		"$top/scripts/slurm-render.sbatch" grid 4x4 scene.txt sl/full.png -s 45 || bad "slurm task $id"
done
check "slurm: 16 tiles" [ "$(ls sl/full.tiles | wc -l)" = 16 ]
"$top/scripts/slurm-render.sbatch" merge-grid 4x4 scene.txt sl/full.png -s 45 >/dev/null
check "slurm: merged 4x4 equals the single render" cmp -s sl/full.png single45.png
for id in 1 2 3 4; do
	SLURM_ARRAY_TASK_ID=$id SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_COUNT=4 \
		"$top/scripts/slurm-render.sbatch" frames 4 scene.txt 'sl/frames/frame-%04d.png' -s 24 || bad "slurm frame task $id"
done
check "slurm: frames equal the sequential run" diff -r sl/frames fr
"$top/scripts/slurm-render.sbatch" merge-frames 4 scene.txt 'sl/frames/frame-%04d.png' >/dev/null
check "slurm: the frames step finds all frames" [ $? = 0 ]
rm sl/frames/frame-0003.png
"$top/scripts/slurm-render.sbatch" merge-frames 4 scene.txt 'sl/frames/frame-%04d.png' >/dev/null 2>&1
check "slurm: the frames step reports a missing frame" [ $? = 1 ]
SLURM_ARRAY_TASK_ID=1 SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_COUNT=9 \
	"$top/scripts/slurm-render.sbatch" grid 4x4 scene.txt sl/x.png -s 45 >/dev/null 2>&1
check "slurm: an array of the wrong size is refused" [ $? = 1 ]
"$top/scripts/slurm-render.sbatch" grid 4x4 scene.txt sl/x.png >/dev/null 2>&1
check "slurm: no SLURM_ARRAY_TASK_ID is an error" [ $? = 1 ]
rm -rf sl/full.tiles sl/full.png
for id in 1 2 3; do
	SLURM_ARRAY_TASK_ID=$id "$top/scripts/slurm-render.sbatch" grid 2x2 scene.txt sl/full.png -s 45
done
"$top/scripts/slurm-render.sbatch" merge-grid 2x2 scene.txt sl/full.png >/dev/null 2>&1
check "slurm: merge with a task missing fails, no output" [ $? = 1 ] && [ ! -e sl/full.png ]
# submit: a stand-in sbatch records the two submissions.
mkdir bin
cat >bin/sbatch <<-'END'
#!/bin/sh
echo "$*" >>"$SBATCH_LOG"
n=$(wc -l <"$SBATCH_LOG")
echo "100$n"
END
chmod +x bin/sbatch
SBATCH_LOG=$tmp/sbatch.log PATH="$tmp/bin:$PATH" "$top/scripts/slurm-render.sbatch" submit grid 4x4 scene.txt sl/full.png -s 45 >/dev/null
check "slurm submit: an array of 16 tasks" grep -q -- "^--parsable --array=1-16 .*slurm-render.sbatch grid 4x4 $tmp/scene.txt $tmp/sl/full.png -s 45" sbatch.log
check "slurm submit: a merge after the array" grep -q -- "^--parsable --dependency=afterok:1001 .*slurm-render.sbatch merge-grid 4x4" sbatch.log
unset WHITTED

# No leaks or memory errors in the new paths (success and failure).
if command -v valgrind >/dev/null 2>&1; then
	vg() { valgrind -q --leak-check=full --show-leak-kinds=all --errors-for-leak-kinds=all --error-exitcode=99 "$@"; }
	vg "$W" -q -s 16 -j 2 --region 3,4,11,13 -o vg-tile.png scene.txt >/dev/null 2>&1
	check "valgrind: region render" [ $? = 0 ]
	rm -rf t && mkdir t
	for k in 1 2 3 4; do "$W" -q -s 16 --grid 2x2 --tile $k -o t/$k.png scene.txt; done
	vg "$W" merge -o vg-m.png t/1.png t/2.png t/3.png t/4.png >/dev/null 2>&1
	check "valgrind: merge" [ $? = 0 ]
	vg "$W" merge -o vg-m2.png t/1.png t/2.png t/3.png t/3.png >/dev/null 2>&1
	check "valgrind: merge of overlapping tiles (exit 1, no errors)" [ $? = 1 ]
	vg "$W" merge -o vg-m2.png t/1.png t/2.png scene.txt full23.png >/dev/null 2>&1
	check "valgrind: merge of non-tiles (exit 1, no errors)" [ $? = 1 ]
	vg "$W" -q -s 12 --frames 3 --path path.txt -o 'vg-%d.png' scene.txt >/dev/null 2>&1
	check "valgrind: frames on a path" [ $? = 0 ]
	vg "$W" -q -s 12 --frames 3 --path badpath.txt -o 'vg-%d.png' scene.txt >/dev/null 2>&1
	check "valgrind: a bad path file (exit 1, no errors)" [ $? = 1 ]
else
	not_run 6 "valgrind is not installed"
fi

echo "dist: $pass passed, $fail failed, $skipped skipped$why"
[ "$fail" = 0 ]
