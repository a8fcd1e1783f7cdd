#!/bin/sh
# End-to-end tests of the whitted command line (filled in by the CLI tests).
echo "clitest: 0 passed, 0 failed"
