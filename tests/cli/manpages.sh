#!/bin/bash
# The man pages of docs/man/ against the programs: every option that a
# program's --help lists is documented in the OPTIONS of its page, and every
# option the OPTIONS mention is in --help (a new option without docs, or a
# removed one still documented, fails); the exit codes of --help are in EXIT
# STATUS; the sections are there; and each page renders without a warning,
# with groff -ww and with man -l (or with mandoc -Tlint where that is the
# formatter).  whitted.1 covers `whitted merge` in its OPTIONS subsection
# titled "whitted merge"; whitted-compare.1 and whitted-grade.1 cover the
# subcommands `whitted compare` and `whitted grade` (git's convention).
SUITE=manpages
. "$(dirname "$0")/lib.sh"
MAN=$ROOT/docs/man
export LC_ALL=C.UTF-8 MANWIDTH=80 MAN_DISABLE_SECCOMP=1

# help_opts PROGRAM [ARGS...]: the options of PROGRAM ARGS --help, one per
# line: the long and short options of the lines that start with an option
# ("  -o, --output FILE", "      --grid CxR --tile K").
help_opts() {
	"$@" --help 2>/dev/null | awk '
		/^ +-/ {
			line = $0
			while (match(line, /--[a-z][a-z0-9-]*/)) {
				print substr(line, RSTART, RLENGTH)
				line = substr(line, RSTART + RLENGTH)
			}
			if (match($0, /^ +-[a-zA-Z],/))
				print substr($0, RSTART + RLENGTH - 3, 2)
		}' | sort -u
}

# help_exits PROGRAM [ARGS...]: the exit codes that --help's "Exit status:"
# paragraph names ("0 success, 1 ..., 128+N when ...").
help_exits() {
	"$@" --help 2>/dev/null | awk '
		/^Exit status:/ { on = 1; sub(/^Exit status:/, "") }
		on && /^$/ { on = 0 }
		on {
			line = " " $0
			while (match(line, /[ ,][0-9]+(\+N)? /)) {
				s = substr(line, RSTART + 1, RLENGTH - 2)
				print s
				line = substr(line, RSTART + RLENGTH - 1)
			}
		}' | sort -u
}

# man_section FILE SECTION [PART]: the roff source of a section, with the
# font escapes, \- and \& \% resolved, as "tag TEXT" (the line after .TP)
# and "text TEXT" lines.  PART "merge" keeps only the subsections whose
# title mentions merge, PART "main" only the others; empty keeps all.
man_section() {
	awk -v want="$2" -v part="$3" '
		function clean(s) {
			gsub(/\\f(\[[^]]*\]|\(..|.)/, "", s)
			gsub(/\\-/, "-", s)
			gsub(/\\[&%]/, "", s)
			gsub(/\\\(mu/, "x", s)
			return s
		}
		/^\.\\"/ { next }
		/^\.SH/ {
			t = $0; sub(/^\.SH +/, "", t); gsub(/"/, "", t)
			on = (t == want); sub_title = ""; next
		}
		!on { next }
		/^\.SS/ { sub_title = $0; next }
		part == "merge" && sub_title !~ /merge/ { next }
		part == "main" && sub_title ~ /merge/ { next }
		/^\.TP/ { tp = 1; next }
		{
			print (tp ? "tag " : "text ") clean($0)
			tp = 0
		}' "$1"
}

# man_opts FILE [PART]: "tag OPT" for each option in an OPTIONS tag (long
# and short), "text OPT" for each long option in the rest of OPTIONS.
man_opts() {
	man_section "$1" OPTIONS "$2" | awk '
		{
			kind = $1; line = " " substr($0, length(kind) + 2) " "
			rest = line
			while (match(rest, /--[a-z][a-z0-9-]*/)) {
				print kind, substr(rest, RSTART, RLENGTH)
				rest = substr(rest, RSTART + RLENGTH)
			}
			if (kind != "tag") next
			rest = line
			while (match(rest, /[ ",(]-[a-zA-Z][ ",)]/)) {
				print kind, substr(rest, RSTART + 1, 2)
				rest = substr(rest, RSTART + 3)
			}
		}' | sort -u
}

# check_options NAME PAGE PART PROGRAM [ARGS...]
check_options() {
	local name=$1 page=$2 part=$3
	shift 3
	local help opts o n=0
	help=$(help_opts "$@")
	opts=$(man_opts "$page" "$part")
	if [ -z "$help" ]; then
		bad "$name" "'$* --help' lists no options"
		return
	fi
	for o in $help; do
		n=$((n + 1))
		if printf '%s\n' "$opts" | grep -qxF -- "tag $o"; then ok
		else bad "$name: $o" "in '$* --help' but not an entry of OPTIONS in ${page#"$ROOT"/}"
		fi
	done
	for o in $(printf '%s\n' "$opts" | cut -d' ' -f2 | sort -u); do
		if printf '%s\n' "$help" | grep -qxF -- "$o"; then ok
		else bad "$name: $o" "in OPTIONS of ${page#"$ROOT"/} but not in '$* --help'"
		fi
	done
}

# check_exits NAME PAGE PROGRAM [ARGS...]: each code of --help's "Exit
# status:" is an entry of EXIT STATUS.
check_exits() {
	local name=$1 page=$2
	shift 2
	local codes tags c
	codes=$(help_exits "$@")
	[ -n "$codes" ] || return 0
	tags=$(man_section "$page" "EXIT STATUS" | sed -n 's/^tag //p' |
		sed -e 's/^\.[A-Z]* *//' -e 's/[" ]//g')
	for c in $codes; do
		if printf '%s\n' "$tags" | grep -qxF -- "$c"; then ok
		else bad "$name: exit $c" "in '$* --help' but not an entry of EXIT STATUS in ${page#"$ROOT"/}"
		fi
	done
}

# The formatter: groff (man-db's) or mandoc, whichever is installed.
if command -v groff >/dev/null 2>&1; then
	fmt=groff
elif command -v mandoc >/dev/null 2>&1; then
	fmt=mandoc
else
	fmt=""
	bad formatter "neither groff nor mandoc is installed (make deps installs man-db)"
fi

# quiet_ok NAME STATUS: the formatter exited 0 and wrote nothing to $T/warn.
quiet_ok() {
	if [ "$2" -eq 0 ] && [ ! -s "$T/warn" ]; then ok; return 0; fi
	bad "$1" "exit status $2, warnings: $(head -5 "$T/warn")"
	return 1
}

check_page() {
	local prog=$1 page=$MAN/$1.1 s upper
	if [ ! -f "$page" ]; then
		bad "$prog.1" "docs/man/$prog.1 is missing"
		return 1
	fi
	for s in NAME SYNOPSIS DESCRIPTION OPTIONS "EXIT STATUS" EXAMPLES "SEE ALSO"; do
		check "$prog.1: section $s" grep -qE "^\.SH \"?$s\"?\$" "$page"
	done
	upper=$(printf '%s' "$prog" | tr a-z A-Z)
	check "$prog.1: .TH $upper 1" grep -qE "^\.TH \"?$upper\"? \"?1\"? " "$page"
	# NAME is "prog \- what", as whatis and mandb read it.
	check "$prog.1: NAME line" [ "$(man_section "$page" NAME | sed -n '1s/^text //p' |
		sed 's/ - .*//')" = "$prog" ]
	case $fmt in
	groff)
		groff -man -Tutf8 -ww -z "$page" 2>"$T/warn"
		quiet_ok "$prog.1: groff -man -Tutf8 -ww" $?
		if command -v man >/dev/null 2>&1; then
			man --warnings -l "$page" >"$T/page" 2>"$T/warn"
			quiet_ok "$prog.1: man -l" $? && check "$prog.1: man -l shows OPTIONS" grep -q '^OPTIONS' "$T/page"
		else
			skip "$prog.1: man -l" "man is not installed (make deps installs man-db)"
		fi
		;;
	mandoc)
		mandoc -Tlint -Wwarning "$page" >"$T/warn" 2>&1
		quiet_ok "$prog.1: mandoc -Tlint" $?
		;;
	esac
	return 0
}

B=$ROOT/build
if check_page whitted; then
	check_options whitted "$MAN/whitted.1" main "$B/whitted"
	check_options "whitted merge" "$MAN/whitted.1" merge "$B/whitted" merge
	check_exits whitted "$MAN/whitted.1" "$B/whitted"
	check_exits "whitted merge" "$MAN/whitted.1" "$B/whitted" merge
fi
for sub in compare grade explain; do
	if check_page "whitted-$sub"; then
		check_options "whitted $sub" "$MAN/whitted-$sub.1" "" "$B/whitted" "$sub"
		check_exits "whitted $sub" "$MAN/whitted-$sub.1" "$B/whitted" "$sub"
	fi
done
if [ ! -x "$B/scene2pov" ]; then
	bad scene2pov "$B/scene2pov is missing (run make all)"
elif check_page scene2pov; then
	check_options scene2pov "$MAN/scene2pov.1" "" "$B/scene2pov"
	check_exits scene2pov "$MAN/scene2pov.1" "$B/scene2pov"
fi
if check_page whitted-view; then
	if [ ! -x "$B/whitted-view" ]; then
		bad whitted-view "$B/whitted-view is not built (freeglut3-dev is missing: make deps), so its --help cannot be checked"
	else
		check_options whitted-view "$MAN/whitted-view.1" "" "$B/whitted-view"
		check_exits whitted-view "$MAN/whitted-view.1" "$B/whitted-view"
	fi
fi
# No page for something that is not one of the programs.
for page in "$MAN"/*.1; do
	p=$(basename "$page" .1)
	case $p in whitted | whitted-compare | whitted-grade | whitted-explain | scene2pov | whitted-view) ok ;; *) bad "$p.1" "a page for no program: $p" ;; esac
done
finish
