/* One Web Worker of the page: the WebAssembly module of whitted (the
 * emscripten code that web/bundle.py puts before this file) and its
 * answers to the page's messages, one at a time:
 *   {op: 'cli', args, files, want}  whitted ARGS (compare, grade, explain):
 *                                   its status, stdout, stderr and the files named in want
 *   {op: 'begin', args, files}      loads and prepares the scene of a render
 *   {op: 'rows', y0, y1}            renders rows [y0, y1) of it: RGB bytes
 *   {op: 'end'}                     frees it
 * Each job's files are written to a fresh folder of the module's memory
 * file system, which is its working directory. */
'use strict';
let whittedModule = null;
let stdoutLines = [];
let stderrLines = [];
let jobCount = 0;
let renderWidth = 0;
const waiting = [];

function setArgs(M, args) {
  M.ccall('web_argv_reset', null, [], []);
  for (const a of ['whitted'].concat(args))
    M.ccall('web_argv_push', 'number', ['string'], [String(a)]);
}

// A fresh working folder with the job's files (text or bytes).
function newJobDir(M, files) {
  const dir = '/job' + (++jobCount);
  M.FS.mkdir(dir);
  M.FS.chdir(dir);
  for (const name of Object.keys(files || {}))
    M.FS.writeFile(dir + '/' + name, files[name]);
  return dir;
}

function removeDir(M, dir) {
  try {
    M.FS.chdir('/');
    for (const name of M.FS.readdir(dir))
      if (name !== '.' && name !== '..')
        M.FS.unlink(dir + '/' + name);
    M.FS.rmdir(dir);
  } catch (e) { /* what could not be removed stays: memory, not a wrong answer */ }
}

let renderDir = null;

function handle(M, msg) {
  stdoutLines = [];
  stderrLines = [];
  const reply = { id: msg.id, status: 0 };
  if (msg.op === 'cli') {
    const dir = newJobDir(M, msg.files);
    setArgs(M, msg.args);
    reply.status = M._web_cli();
    reply.files = {};
    for (const name of msg.want || []) {
      try {
        // whitted gives a new file the permissions the umask leaves,
        // none under emscripten's: make it readable first.
        M.FS.chmod(dir + '/' + name, 0o644);
        reply.files[name] = M.FS.readFile(dir + '/' + name);
      } catch (e) { /* not written */ }
    }
    removeDir(M, dir);
  } else if (msg.op === 'begin') {
    if (renderDir) {
      M._web_render_end();
      removeDir(M, renderDir);
    }
    renderDir = newJobDir(M, msg.files);
    setArgs(M, msg.args);
    reply.status = M._web_render_begin();
    reply.width = renderWidth = M._web_render_width();
    reply.height = M._web_render_height();
  } else if (msg.op === 'rows') {
    const n = renderWidth * (msg.y1 - msg.y0) * 3;
    const p = M._malloc(Math.max(n, 1));
    reply.status = M._web_render_rows(msg.y0, msg.y1, p);
    reply.y0 = msg.y0;
    reply.y1 = msg.y1;
    reply.rgb = M.HEAPU8.slice(p, p + n);
    M._free(p);
  } else if (msg.op === 'end') {
    M._web_render_end();
    if (renderDir)
      removeDir(M, renderDir);
    renderDir = null;
  }
  reply.stdout = stdoutLines.length ? stdoutLines.join('\n') + '\n' : '';
  reply.stderr = stderrLines.slice();
  return reply;
}

function serve(msg) {
  let reply;
  try {
    reply = handle(whittedModule, msg);
  } catch (e) {
    reply = { id: msg.id, status: 70, stdout: '', stderr: stderrLines.concat(['whitted: error: ' + e]) };
  }
  postMessage(reply, reply.rgb ? [reply.rgb.buffer] : []);
}

onmessage = (e) => {
  if (!whittedModule)
    waiting.push(e.data);
  else
    serve(e.data);
};

createWhittedModule({
  print: (s) => stdoutLines.push(s),
  printErr: (s) => stderrLines.push(s),
}).then((M) => {
  whittedModule = M;
  postMessage({ ready: true });
  while (waiting.length)
    serve(waiting.shift());
});
