# The counts of the image checks (threadcheck.sh, portablecheck.sh,
# embreecheck.sh), sourced by each so that a check's pass or failure is
# counted and said one way.  The sourcing script sets CHECK, the name its
# messages start with, before it sources this file.
# shellcheck shell=sh
pass=0 fail=0

# failed WHY: one check failed, saying WHY.
failed() {
	echo "$CHECK: $1"
	fail=$((fail + 1))
}

# same A B WHY: passes when the files A and B are the same byte for byte,
# fails saying WHY when they are not.
same() {
	if cmp -s "$1" "$2"; then
		pass=$((pass + 1))
	else
		failed "$3"
	fi
}
