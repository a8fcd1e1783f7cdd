#!/usr/bin/env python3
"""Makes the page's folder: web/index.html with the style, the worker's
code (emscripten's module, its WebAssembly inlined in base64, then
web/worker.js) in a script element of type text/plain that the page turns
into a Blob for its workers, the default scene, and the page's scripts, all
in one index.html, which opens from disk and from any static host.
Usage: bundle.py WASM_JS WEB_DIR OUT_DIR"""
import html, os, sys

wasm_js, web, out = sys.argv[1:4]
root = os.path.dirname(os.path.abspath(web))

def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()

def script_safe(text, what):
    # Nothing inside may end the script element early.
    if "</script" in text.lower() or "<!--" in text:
        sys.exit("bundle.py: %s contains '</script' or '<!--'" % what)
    return text

page = read(os.path.join(web, "index.html"))
parts = {
    "STYLE": read(os.path.join(web, "style.css")),
    "WORKER": script_safe(read(wasm_js) + "\n" + read(os.path.join(web, "worker.js")), "the worker"),
    "EXAMPLE": html.escape(read(os.path.join(root, "scenes", "scene.txt"))),
    "API": script_safe(read(os.path.join(web, "whitted-api.js")), "whitted-api.js"),
    "APP": script_safe(read(os.path.join(web, "report.js")) + "\n" + read(os.path.join(web, "app.js")),
                       "the page's scripts"),
}
for key, text in parts.items():
    marker = "@%s@" % key
    if page.count(marker) != 1:
        sys.exit("bundle.py: %s must appear once in web/index.html" % marker)
    page = page.replace(marker, text)
os.makedirs(out, exist_ok=True)
tmp = os.path.join(out, ".index.html.tmp")
with open(tmp, "w", encoding="utf-8") as f:
    f.write(page)
os.replace(tmp, os.path.join(out, "index.html"))
print("bundle.py: wrote %s (%d bytes)" % (os.path.join(out, "index.html"), len(page.encode())))
