#!/usr/bin/env python3
"""The module map, checked: which folder of src/ includes which, from the
#include lines (a private header "base/alloc.h" belongs to src/base, a public
"whitted/x.h" to the module whose folder holds x.c), and the link-level
references that #includes do not show (a function defined in one folder and
called from another, read from the objects with nm).  Fails on a cycle
between folders, on a library module that includes program code (src/cli)
or getopt, and on an installed header that includes anything private.
Prints the graph.  Usage: modules.py [BUILD_DIR]"""
import os, re, subprocess, sys

root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
build = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build")
src = os.path.join(root, "src")
modules = sorted(d for d in os.listdir(src) if os.path.isdir(os.path.join(src, d)))
failures = []

def sources(m):
    return [os.path.join(src, m, f) for f in sorted(os.listdir(os.path.join(src, m)))
            if f.endswith((".c", ".h"))]

include_re = re.compile(r'^\s*#\s*include\s+[<"]([^">]+)[">]', re.M)
edges = {m: set() for m in modules}
why = {}

# Link-level: symbols each module's objects define and use.
defined, used = {}, {m: set() for m in modules}
for m in modules:
    objdir = os.path.join(build, "src", m)
    if not os.path.isdir(objdir):
        failures.append("no objects in %s: build first (make all)" % objdir)
        continue
    for f in sorted(os.listdir(objdir)):
        if not f.endswith(".o"):
            continue
        out = subprocess.run(["nm", os.path.join(objdir, f)], capture_output=True,
                             text=True, check=True).stdout
        for line in out.splitlines():
            parts = line.split()
            if len(parts) == 3 and parts[1] in "TDBR":
                defined[parts[2]] = m
            elif len(parts) == 2 and parts[0] == "U":
                used[m].add(parts[1])
for m in modules:
    for sym in used[m]:
        d = defined.get(sym)
        if d and d != m:
            edges[m].add(d)
            why.setdefault((m, d), "calls %s" % sym)

for m in modules:
    for f in sources(m):
        text = open(f, encoding="utf-8").read()
        for inc in include_re.findall(text):
            if inc == "getopt.h" and m != "cli":
                failures.append("%s includes getopt.h: the library reads no argv" % f)
            head = inc.split("/")[0]
            if head in modules and head != m:
                edges[m].add(head)
                why.setdefault((m, head), "includes %s" % inc)

# The library must not depend on the programs' code.
for m in modules:
    if m != "cli" and "cli" in edges[m]:
        failures.append("library module %s depends on src/cli (%s)" % (m, why[(m, "cli")]))

# Cycles: depth-first search over the folders.
state, stack = {}, []
def visit(m):
    state[m] = 1
    stack.append(m)
    for n in sorted(edges[m]):
        if state.get(n) == 1:
            cyc = stack[stack.index(n):] + [n]
            failures.append("cycle between folders: " + " -> ".join(
                "%s" % c for c in cyc) + " (" + "; ".join(
                "%s %s" % (a, why[(a, b)]) for a, b in zip(cyc, cyc[1:])) + ")")
        elif n not in state:
            visit(n)
    stack.pop()
    state[m] = 2
for m in modules:
    if m not in state:
        visit(m)

# Installed headers include only the C library and each other.
pubdir = os.path.join(root, "include", "whitted")
public = set(os.listdir(pubdir))
for h in sorted(public):
    for inc in include_re.findall(open(os.path.join(pubdir, h), encoding="utf-8").read()):
        if "/" in inc or (inc.endswith(".h") and inc not in public and not re.match(
                r"^(std\w*|math|signal|string|limits|float|errno|assert)\.h$", inc)):
            failures.append("include/whitted/%s includes %s: not part of the installed API" % (h, inc))
        if inc in ("pthread.h", "getopt.h"):
            failures.append("include/whitted/%s includes %s" % (h, inc))

# Layers, from the bottom: each module with the modules it uses.
order, placed = [], set()
while len(order) < len(modules):
    ready = [m for m in modules if m not in placed and edges[m] - {m} <= placed]
    if not ready:
        break
    for m in ready:
        order.append(m)
        placed.add(m)
for m in order:
    print("layout: %-10s uses %s" % (m, ", ".join(sorted(edges[m])) or "-"))
for f in failures:
    print("layout: FAIL: " + f)
# Four checks: no getopt in the library, no library module on src/cli, no
# cycle, installed headers self-contained.
print("layout: %d passed, %d failed, 0 skipped" % (0 if failures else 4, len(failures)))
sys.exit(1 if failures else 0)
