#!/usr/bin/env python3
"""The module map, checked: which folder of src/ includes which, from the
#include lines (a private header "base/alloc.h" belongs to src/base, a public
"whitted/x.h" to the module whose folder holds x.c), and the link-level
references that #includes do not show (a function defined in one folder and
called from another, read from the objects with nm).  Fails on a cycle
between folders, on a cycle between the files of a folder (file a.c uses
b.c when it calls a function or reads data b.c defines), on a C file of
more than 500 lines, on a function of more than 60 without a "Long:"
reason in the comment above it, on a library module that includes program code
(src/cli) or getopt, and on an installed header that includes anything
private.  Prints the graph.  Usage: modules.py [BUILD_DIR]"""
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

# Link-level: symbols each module's objects define and use (and, file by
# file, each object's).
defined, used = {}, {m: set() for m in modules}
file_defined, file_used = {}, {}
for m in modules:
    objdir = os.path.join(build, "src", m)
    if not os.path.isdir(objdir):
        failures.append("no objects in %s: build first (make all)" % objdir)
        continue
    for f in sorted(os.listdir(objdir)):
        if not f.endswith(".o"):
            continue
        node = "%s/%s" % (m, f[:-2])
        out = subprocess.run(["nm", os.path.join(objdir, f)], capture_output=True,
                             text=True, check=True).stdout
        for line in out.splitlines():
            parts = line.split()
            if len(parts) == 3 and parts[1] in "TDBR":
                defined[parts[2]] = m
                file_defined[parts[2]] = node
            elif len(parts) == 2 and parts[0] == "U":
                used[m].add(parts[1])
                file_used.setdefault(node, set()).add(parts[1])
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

# Cycles between the files of a folder: a.c uses b.c when it calls what
# b.c defines (read from the objects: a header often declares the
# functions of several files, so an #include says less).
file_edges, file_why = {}, {}
for node, syms in file_used.items():
    for sym in sorted(syms):
        d = file_defined.get(sym)
        if d and d != node and d.split("/")[0] == node.split("/")[0]:
            file_edges.setdefault(node, set()).add(d)
            file_why.setdefault((node, d), "calls %s" % sym)
fstate, fstack, file_cycles = {}, [], set()
def fvisit(n):
    fstate[n] = 1
    fstack.append(n)
    for k in sorted(file_edges.get(n, ())):
        if fstate.get(k) == 1:
            cyc = fstack[fstack.index(k):] + [k]
            key = frozenset(cyc)
            if key not in file_cycles:
                file_cycles.add(key)
                failures.append("cycle between files: " + " -> ".join(cyc) + " (" + "; ".join(
                    "%s %s" % (a, file_why[(a, b)]) for a, b in zip(cyc, cyc[1:])) + ")")
        elif k not in fstate:
            fvisit(k)
    fstack.pop()
    fstate[n] = 2
for n in sorted(set(file_edges) | {k for v in file_edges.values() for k in v}):
    if n not in fstate:
        fvisit(n)

# Small files: no C source or header over 500 lines, the house's limit.
MAX_LINES = 500
for top in ("src", "include", "pov_export", "viewer", "plugins"):
    for dirpath, _, names in os.walk(os.path.join(root, top)):
        for name in sorted(names):
            if name.endswith((".c", ".h")):
                path = os.path.join(dirpath, name)
                with open(path, encoding="utf-8") as fh:
                    lines = sum(1 for _ in fh)
                if lines > MAX_LINES:
                    failures.append("%s has %d lines, over the house's %d" % (
                        os.path.relpath(path, root), lines, MAX_LINES))

# A function over 60 lines says why above it: a "Long:" in the comment
# that sits on it (#define lines between them allowed).
MAX_FUNCTION = 60
def long_functions(path):
    lines = open(path, encoding="utf-8").read().split("\n")
    i = 0
    while i < len(lines):
        if lines[i].startswith("{") and i > 0:
            start = i - 1
            while start > 0 and lines[start][:1] in ("\t", " "):
                start -= 1
            end = i + 1
            while end < len(lines) and not lines[end].startswith("}"):
                end += 1
            if end - start + 1 > MAX_FUNCTION:
                above = start - 1
                while above >= 0 and (lines[above].startswith("#define") or not lines[above].strip()):
                    above -= 1
                comment = []
                while above >= 0 and (lines[above].startswith((" *", "/*"))):
                    comment.append(lines[above])
                    if lines[above].startswith("/*"):
                        break
                    above -= 1
                if not any("Long:" in c for c in comment):
                    yield start + 1, end - start + 1, lines[start].strip()
            i = end
        i += 1
for top in ("src", "pov_export", "viewer", "plugins", "web"):
    for dirpath, _, names in os.walk(os.path.join(root, top)):
        for name in sorted(names):
            if name.endswith((".c", ".h")):
                path = os.path.join(dirpath, name)
                for line, n, sig in long_functions(path):
                    failures.append("%s:%d: a function of %d lines with no \"Long:\" reason "
                                    "above it: %s" % (os.path.relpath(path, root), line, n, sig[:60]))

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
# Seven checks: no getopt in the library, no library module on src/cli,
# no cycle between folders, none between files, no file over 500 lines,
# no long function without its reason, installed headers self-contained.
print("layout: %d passed, %d failed, 0 skipped" % (0 if failures else 7, len(failures)))
sys.exit(1 if failures else 0)
