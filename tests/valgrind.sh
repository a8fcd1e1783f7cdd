#!/bin/sh
# The CLI under valgrind (filled in by the memory tests).
echo "valgrind: 0 passed, 0 failed"
