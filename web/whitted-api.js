/* window.whitted: the page's one API, which its controls and its tests use.
 *   ready                            a Promise: the workers are started
 *   render(sceneText, options)       -> {width, height, rgba, notes}
 *   compare(sceneText, imageBytes, options) -> whitted compare --json's object
 *   explain(sceneText, x, y, options)       -> whitted explain --json's object
 *   grade(sceneText, images, options)       -> {status, table, csv}
 *   args(options), command(name, options)   the command line of whitted
 * options are named as whitted's long options (size, recursion, eye, look,
 * up, fov, floor, 'no-floor', clamp, samples, glass, 'floor-texture',
 * dialect, lenient, 'max-rays'); besides them: name (the scene file's
 * name, 'scene.txt'), files ({name: bytes}, e.g. the floor's textures),
 * onprogress(done, total) for render, imageName for compare, diff (true:
 * the result's non-enumerable `diff` holds the difference picture, PNG).
 * A bad scene rejects with an Error whose message is whitted's
 * 'FILE:LINE:COL: error: ...' line.  Rendering runs in Web Workers, one a
 * hardware thread, each loading the scene and rendering bands of rows that
 * it takes in turn: the page stays responsive and the image is the CLI's,
 * byte for byte. */
(function () {
  'use strict';
  const PAGE_KEYS = new Set(['name', 'files', 'onprogress', 'imageName', 'diff', 'threads']);
  const FLAGS = new Set(['no-floor', 'lenient', 'test-scene', 'quiet']);
  const BAND = 16;

  function args(options) {
    const out = [];
    for (const [key, value] of Object.entries(options || {})) {
      if (PAGE_KEYS.has(key) || value === undefined || value === null || value === false || value === '')
        continue;
      if (FLAGS.has(key) || value === true) {
        out.push('--' + key);
        continue;
      }
      for (const v of Array.isArray(value) ? value : [value])
        out.push('--' + key, Array.isArray(v) ? v.join(',') : String(v));
    }
    return out;
  }

  function quote(a) {
    return /^[A-Za-z0-9_.,:\/=+-]+$/.test(a) ? a : "'" + a.replace(/'/g, "'\\''") + "'";
  }

  function command(name, options, sub) {
    return ['whitted'].concat(sub || [], args(options), [name || 'scene.txt']).map(quote).join(' ');
  }

  // The error of a failed run: whitted's 'error:' line (else its first).
  function runError(reply) {
    const lines = reply.stderr || [];
    const line = lines.find((l) => / error: /.test(l)) || lines[0] ||
      'whitted: error: exit status ' + reply.status;
    const e = new Error(line);
    e.status = reply.status;
    e.stderr = lines;
    return e;
  }

  function notesOf(reply) {
    return (reply.stderr || []).filter((l) => / note: /.test(l));
  }

  class Worker1 {
    constructor(url) {
      this.w = new Worker(url);
      this.next = 1;
      this.pending = new Map();
      this.load = 0;
      this.ready = new Promise((resolve, reject) => {
        this.w.onerror = (e) => reject(new Error('whitted: error: the worker failed: ' + (e.message || e)));
        this.w.onmessage = (e) => {
          if (e.data.ready) {
            resolve();
            return;
          }
          const p = this.pending.get(e.data.id);
          this.pending.delete(e.data.id);
          this.load--;
          p(e.data);
        };
      });
    }

    call(msg, transfer) {
      const id = this.next++;
      this.load++;
      return new Promise((resolve) => {
        this.pending.set(id, resolve);
        this.w.postMessage(Object.assign({ id }, msg), transfer || []);
      });
    }
  }

  const source = document.getElementById('whitted-worker').textContent;
  const url = URL.createObjectURL(new Blob([source], { type: 'text/javascript' }));
  const threads = Math.max(1, Math.min(64, navigator.hardwareConcurrency || 2));
  const workers = [];
  for (let i = 0; i < threads; i++)
    workers.push(new Worker1(url));
  const ready = Promise.all(workers.map((w) => w.ready)).then(() => {
    performance.mark('whitted-ready');
  });
  let generation = 0;

  function sceneFiles(sceneText, options) {
    const name = (options && options.name) || 'scene.txt';
    const files = Object.assign({}, (options && options.files) || {});
    files[name] = sceneText;
    return { name, files };
  }

  function leastBusy() {
    return workers.reduce((a, b) => (b.load < a.load ? b : a));
  }

  async function render(sceneText, options) {
    options = options || {};
    await ready;
    const mine = ++generation;
    const { name, files } = sceneFiles(sceneText, options);
    const argv = args(options).concat([name]);
    const team = workers.slice(0, Math.max(1, Math.min(workers.length, options.threads || workers.length)));
    const begun = await Promise.all(team.map((w) => w.call({ op: 'begin', args: argv, files })));
    const bad = begun.find((r) => r.status !== 0);
    if (bad)
      throw runError(bad);
    const width = begun[0].width, height = begun[0].height;
    const rgba = new Uint8ClampedArray(width * height * 4);
    const bands = Math.ceil(height / BAND);
    let next = 0, done = 0, failure = null;
    // Each worker has two bands asked of it at a time, so that it starts
    // the next while the page takes in the last.
    async function work(w) {
      const asked = [];
      const ask = () => {
        if (next >= bands || failure)
          return;
        if (mine !== generation) {
          failure = new Error('whitted: render superseded by a newer one');
          failure.name = 'AbortError';
          return;
        }
        const y0 = (next++) * BAND, y1 = Math.min(height, y0 + BAND);
        asked.push(w.call({ op: 'rows', y0, y1 }));
      };
      ask();
      ask();
      while (asked.length) {
        const r = await asked.shift();
        if (r.status !== 0) {
          failure = failure || runError(r);
          continue;
        }
        ask();
        for (let i = 0, o = r.y0 * width * 4; i < r.rgb.length; i += 3, o += 4) {
          rgba[o] = r.rgb[i];
          rgba[o + 1] = r.rgb[i + 1];
          rgba[o + 2] = r.rgb[i + 2];
          rgba[o + 3] = 255;
        }
        done++;
        if (options.onprogress)
          options.onprogress(done, bands);
      }
    }
    await Promise.all(team.map(work));
    // The workers keep the scene until the next render's 'begin' frees it
    // (an 'end' here could reach a worker after a newer render's begin).
    if (failure)
      throw failure;
    return { width, height, rgba, notes: notesOf(begun[0]), command: command(name, options) };
  }

  async function cli(argv, files, want) {
    await ready;
    return leastBusy().call({ op: 'cli', args: argv, files, want: want || [] });
  }

  async function compare(sceneText, imageBytes, options) {
    options = options || {};
    const { name, files } = sceneFiles(sceneText, options);
    const image = options.imageName || 'image.png';
    files[image] = imageBytes;
    const argv = ['compare', '--json'].concat(options.diff ? ['--diff', 'diff.png'] : [],
      args(options), [name, image]);
    const r = await cli(argv, files, ['diff.png']);
    if (r.status !== 0 && r.status !== 3)
      throw runError(r);
    const result = JSON.parse(r.stdout);
    if (options.diff && r.files['diff.png'])
      Object.defineProperty(result, 'diff', { value: r.files['diff.png'], enumerable: false });
    Object.defineProperty(result, 'notes', { value: notesOf(r), enumerable: false });
    return result;
  }

  async function explain(sceneText, x, y, options) {
    const { name, files } = sceneFiles(sceneText, options);
    const r = await cli(['explain', '--json'].concat(args(options), [name, x + ',' + y]), files);
    if (r.status !== 0)
      throw runError(r);
    return JSON.parse(r.stdout);
  }

  // images: [{name, bytes}].  The table is grade's stdout, csv its CSV.
  async function grade(sceneText, images, options) {
    const { name, files } = sceneFiles(sceneText, options);
    const names = [];
    for (const im of images) {
      files[im.name] = im.bytes;
      names.push(im.name);
    }
    const argv = ['grade', '--scene', name, '--csv', 'marks.csv'].concat(args(options), names);
    const r = await cli(argv, files, ['marks.csv']);
    if (r.status !== 0 && r.status !== 3)
      throw runError(r);
    const csv = r.files['marks.csv'] ? new TextDecoder().decode(r.files['marks.csv']) : '';
    return { status: r.status, table: r.stdout, csv };
  }

  window.whitted = { ready, render, compare, explain, grade, args, command, threads };
})();
