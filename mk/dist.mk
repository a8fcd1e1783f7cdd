# Region renders, the merge, frames and their distribution (issue 7):
# tests/dist/run.sh runs them end to end, GNU parallel locally and over ssh
# to a private sshd on localhost (--transfer needs rsync), and the Slurm
# script with its array variables set by hand.
OPTIONAL_PKGS += parallel openssh-client openssh-server rsync
CHECK_TARGETS += disttest

.PHONY: disttest
disttest: all
	@tests/dist/run.sh
