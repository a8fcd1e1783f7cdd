/* The page's controls, through window.whitted: a scene opened or dropped
 * (the course's example at first), rendered with the form's options, the
 * command line that reproduces the image, downloads, the camera flown with
 * the keys of whitted-view and orbited with the mouse, a click that
 * explains a pixel, and students' images dropped for compare (one) or
 * grade (several).  A scene's error is shown at its line and column in a
 * view of the file. */
'use strict';
(function () {
  const $ = (id) => document.getElementById(id);
  const canvas = $('canvas'), ctx = canvas.getContext('2d');
  const state = {
    text: $('example-scene').value, bytes: null, name: 'scene.txt', textures: {}, camera: null,
    image: null, step: 10, turn: 5 * Math.PI / 180, busy: false, again: false, preview: false,
  };

  // ---- vectors, the fly camera of viewer/fly_camera.c ----
  const add = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
  const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
  const scale = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
  const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const norm = (a) => scale(a, 1 / Math.sqrt(dot(a, a)));
  const parseVec = (s, def) => {
    const v = String(s || '').split(',').map(Number);
    return v.length === 3 && v.every(Number.isFinite) ? v : def;
  };
  const short = (v) => v.map((x) => Number(x.toPrecision(7))).join(',');

  function cameraFromForm() {
    const f = $('options').elements;
    const eye = parseVec(f.eye.value, [0, -200, 10]), look = parseVec(f.look.value, [0, 0, 0]);
    const up0 = parseVec(f.up.value, [0, 0, 1]);
    const forward = norm(sub(look, eye));
    const right = norm(cross(forward, up0));
    return { eye, forward, up: cross(right, forward), dist: Math.sqrt(dot(sub(look, eye), sub(look, eye))) };
  }

  function orthonormalize(c) {
    c.forward = norm(c.forward);
    c.up = norm(sub(c.up, scale(c.forward, dot(c.up, c.forward))));
  }

  function rotatePair(a, b, angle) {
    const co = Math.cos(angle), si = Math.sin(angle);
    return [add(scale(a, co), scale(b, si)), sub(scale(b, co), scale(a, si))];
  }

  // The camera into the form, rounded as the command line shows it.
  function cameraToForm(c) {
    const f = $('options').elements;
    f.eye.value = short(c.eye);
    f.look.value = short(add(c.eye, scale(c.forward, Math.max(1, c.dist))));
    f.up.value = short(c.up);
  }

  // ---- options and rendering ----
  const scene = () => state.bytes || state.text;

  function options(preview) {
    const f = $('options').elements, o = { name: state.name };
    for (const key of ['size', 'recursion', 'samples', 'eye', 'look', 'up', 'fov', 'floor', 'glass', 'clamp'])
      if (f[key].value.trim() !== '')
        o[key] = f[key].value.trim();
    if (f['no-floor'].checked)
      o['no-floor'] = true;
    const tex = Object.keys(state.textures);
    if (tex.length) {
      o['floor-texture'] = tex.join(',');
      o.files = state.textures;
    }
    if (preview) {
      o.size = Math.min(Number(o.size || state.image && state.image.width || 256), 192);
      delete o.samples;
    }
    return o;
  }

  function showError(e) {
    // No image and no command for a scene that does not read.
    canvas.hidden = true;
    $('command').value = '';
    $('error').hidden = false;
    $('error-message').textContent = e.message;
    const pre = $('error-file');
    pre.replaceChildren();
    const m = /^([^:]*):(\d+):(\d+): error:/.exec(e.message);
    const lines = state.text.split(/\r?\n/);
    const at = m ? Number(m[2]) : 0, col = m ? Number(m[3]) : 0;
    lines.forEach((line, i) => {
      const n = i + 1;
      const span = el('span', { class: n === at ? 'bad' : '', 'data-line': String(n) },
        String(n).padStart(4) + '  ' + line + '\n');
      pre.append(span);
      if (n === at)
        pre.append(el('span', { class: 'caret', id: 'error-caret' }, ' '.repeat(5 + Math.max(col, 1)) + '^ ' + e.message.replace(/^.*? error: /, '') + '\n'));
    });
    const bad = pre.querySelector('.bad');
    if (bad)
      bad.scrollIntoView({ block: 'center' });
  }

  function setProgress(done, total) {
    const p = Math.round(100 * done / total);
    $('progress').firstElementChild.style.width = p + '%';
    $('progress').setAttribute('aria-valuenow', String(p));
  }

  async function render(preview) {
    if (state.busy) {
      state.again = true;
      state.preview = preview;
      return;
    }
    state.busy = true;
    const o = options(preview);
    setProgress(0, 1);
    $('status').textContent = preview ? 'previewing...' : 'rendering...';
    const t0 = performance.now();
    try {
      const img = await whitted.render(scene(), Object.assign({ onprogress: setProgress }, o));
      canvas.width = img.width;
      canvas.height = img.height;
      // A small image is shown larger, its pixels square.
      canvas.style.width = (img.width < 384 ? 384 : img.width) + 'px';
      ctx.putImageData(new ImageData(img.rgba, img.width, img.height), 0, 0);
      state.image = img;
      canvas.hidden = false;
      $('error').hidden = true;
      if (!preview) {
        const cmdOptions = Object.assign({}, o);
        delete cmdOptions.files;
        $('command').value = whitted.command(state.name, cmdOptions);
        $('status').textContent = img.notes.join(' ') + ' (' + img.width + 'x' + img.height + ', ' +
          Math.round(performance.now() - t0) + ' ms, ' + whitted.threads + ' workers)';
        document.body.dataset.rendered = String(Number(document.body.dataset.rendered || 0) + 1);
        updateDownloads();
      }
    } catch (e) {
      if (e.name !== 'AbortError') {
        $('status').textContent = 'error';
        showError(e);
        document.body.dataset.failed = String(Number(document.body.dataset.failed || 0) + 1);
      }
    } finally {
      state.busy = false;
      if (state.again) {
        state.again = false;
        render(state.preview);
      }
    }
  }

  // ---- downloads: the canvas's PNG, and a 24-bit bottom-up BMP ----
  function bmpBytes(img) {
    const row = Math.ceil(img.width * 3 / 4) * 4, size = 54 + row * img.height;
    const b = new Uint8Array(size), v = new DataView(b.buffer);
    b[0] = 66; b[1] = 77;
    v.setUint32(2, size, true); v.setUint32(10, 54, true); v.setUint32(14, 40, true);
    v.setInt32(18, img.width, true); v.setInt32(22, img.height, true);
    v.setUint16(26, 1, true); v.setUint16(28, 24, true); v.setUint32(34, row * img.height, true);
    for (let y = 0; y < img.height; y++)
      for (let x = 0; x < img.width; x++) {
        const s = ((img.height - 1 - y) * img.width + x) * 4, d = 54 + y * row + x * 3;
        b[d] = img.rgba[s + 2]; b[d + 1] = img.rgba[s + 1]; b[d + 2] = img.rgba[s];
      }
    return b;
  }

  function updateDownloads() {
    const base = state.name.replace(/\.[^.]*$/, '') || 'scene';
    canvas.toBlob((blob) => {
      $('download-png').href = URL.createObjectURL(blob);
      $('download-png').download = base + '.png';
    }, 'image/png');
    $('download-bmp').href = URL.createObjectURL(new Blob([bmpBytes(state.image)], { type: 'image/bmp' }));
    $('download-bmp').download = base + '.bmp';
  }

  // ---- files: scenes, textures, students' images ----
  const isImage = (name) => /\.(png|bmp|ppm)$/i.test(name);
  const readBytes = (file) => file.arrayBuffer().then((b) => new Uint8Array(b));

  async function openScene(file) {
    // The bytes go to whitted as read (a byte order mark, CRLF, any
    // encoding); the text is for the view of an error.
    state.bytes = await readBytes(file);
    state.text = new TextDecoder('utf-8').decode(state.bytes);
    state.name = file.name.replace(/[^A-Za-z0-9._-]/g, '_') || 'scene.txt';
    $('scene-name').textContent = file.name;
    $('explain').replaceChildren();
    render(false);
  }

  async function checkImages(files) {
    const o = options(false);
    if (files.length === 1) {
      $('compare-report').replaceChildren(el('p', {}, 'comparing ' + files[0].name + '...'));
      try {
        const res = await whitted.compare(scene(), await readBytes(files[0]),
          Object.assign(o, { imageName: files[0].name.replace(/[^A-Za-z0-9._-]/g, '_'), diff: true }));
        showCompare(res, $('compare-report'), files[0].name);
        showStudentImage(files[0]);
      } catch (e) {
        $('compare-report').replaceChildren(el('p', { id: 'compare-error' }, e.message));
      }
      return;
    }
    $('grade-report').replaceChildren(el('p', {}, 'grading ' + files.length + ' images...'));
    const images = [];
    for (const f of files)
      images.push({ name: f.name.replace(/[^A-Za-z0-9._-]/g, '_'), bytes: await readBytes(f) });
    try {
      showGrade(await whitted.grade(scene(), images, o), $('grade-report'));
    } catch (e) {
      $('grade-report').replaceChildren(el('p', {}, e.message));
    }
  }

  // The student's image beside the report (what the browser can show:
  // PNG and BMP): a click explains that pixel of the reference, with the
  // student's own value beside it.
  function showStudentImage(file) {
    if (!/\.(png|bmp)$/i.test(file.name))
      return;
    const img = el('img', { id: 'student-image', alt: 'your image', src: URL.createObjectURL(file) });
    img.style.cursor = 'crosshair';
    img.addEventListener('click', async (e) => {
      const r = img.getBoundingClientRect();
      const x = Math.min(img.naturalWidth - 1, Math.floor((e.clientX - r.left) * img.naturalWidth / r.width));
      const y = Math.min(img.naturalHeight - 1, Math.floor((e.clientY - r.top) * img.naturalHeight / r.height));
      // Decoded from the file's bytes (a page opened from disk may not read
      // back an <img> drawn on a canvas).
      const bitmap = await createImageBitmap(file);
      const c = document.createElement('canvas');
      c.width = bitmap.width;
      c.height = bitmap.height;
      const g = c.getContext('2d');
      g.drawImage(bitmap, 0, 0);
      const v = g.getImageData(x, y, 1, 1).data;
      await explainPixel(x, y);
      $('explain').prepend(el('p', { id: 'student-value' }, 'your image has (' + v[0] + ', ' + v[1] + ', ' + v[2] + ') there'));
    });
    $('compare-report').append(el('p', {}, 'Your image (click a pixel to explain the reference\'s):'), img);
  }

  async function takeFiles(list) {
    const files = Array.from(list);
    const images = files.filter((f) => isImage(f.name)), scenes = files.filter((f) => !isImage(f.name));
    if (scenes.length)
      await openScene(scenes[0]);
    if (images.length)
      checkImages(images);
  }

  $('scene-input').addEventListener('change', (e) => takeFiles(e.target.files));
  $('image-input').addEventListener('change', (e) => checkImages(Array.from(e.target.files)));
  $('texture-input').addEventListener('change', async (e) => {
    state.textures = {};
    for (const f of Array.from(e.target.files).slice(0, 2))
      state.textures['texture-' + Object.keys(state.textures).length + f.name.replace(/^.*(\.[A-Za-z]+)$/, '$1')] = await readBytes(f);
    $('texture-names').textContent = Array.from(e.target.files).map((f) => f.name).join(', ');
    render(false);
  });
  document.addEventListener('dragover', (e) => {
    e.preventDefault();
    document.body.classList.add('dragging');
  });
  document.addEventListener('dragleave', () => document.body.classList.remove('dragging'));
  document.addEventListener('drop', (e) => {
    e.preventDefault();
    document.body.classList.remove('dragging');
    takeFiles(e.dataTransfer.files);
  });
  $('options').addEventListener('submit', (e) => {
    e.preventDefault();
    render(false);
  });
  $('camera-reset').addEventListener('click', () => {
    for (const k of ['eye', 'look', 'up'])
      $('options').elements[k].value = '';
    render(false);
  });

  // ---- the camera: keys as whitted-view's, the mouse orbits ----
  function moved(preview) {
    cameraToForm(state.camera);
    render(preview);
  }

  canvas.addEventListener('keydown', (e) => {
    const c = state.camera = cameraFromForm(), s = state.step, t = state.turn;
    const right = cross(c.forward, c.up);
    let p;
    switch (e.key) {
    case 'ArrowUp': c.eye = add(c.eye, scale(c.forward, s)); break;
    case 'ArrowDown': c.eye = add(c.eye, scale(c.forward, -s)); break;
    case 'ArrowLeft': c.eye = add(c.eye, scale(right, -s)); break;
    case 'ArrowRight': c.eye = add(c.eye, scale(right, s)); break;
    case 'PageUp': c.eye = add(c.eye, scale(c.up, s)); break;
    case 'PageDown': c.eye = add(c.eye, scale(c.up, -s)); break;
    case '1': case '2':
      p = rotatePair(c.forward, scale(right, -1), e.key === '1' ? t : -t);
      c.forward = p[0];
      break;
    case '3': case '4':
      p = rotatePair(c.forward, c.up, e.key === '3' ? t : -t);
      c.forward = p[0];
      c.up = p[1];
      break;
    case '5': case '6':
      p = rotatePair(c.up, right, e.key === '5' ? t : -t);
      c.up = p[0];
      break;
    case '+': case '=': state.step *= 2; state.turn *= 2; return;
    case '-': case '_': state.step /= 2; state.turn /= 2; return;
    case 'r': case 'R': $('camera-reset').click(); return;
    default: return;
    }
    e.preventDefault();
    orthonormalize(c);
    moved(false);
  });

  let drag = null;
  canvas.addEventListener('mousedown', (e) => {
    drag = { x: e.clientX, y: e.clientY, moved: false };
    canvas.focus();
  });
  window.addEventListener('mousemove', (e) => {
    if (!drag)
      return;
    const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
    if (!drag.moved && Math.abs(dx) + Math.abs(dy) < 4)
      return;
    drag.moved = true;
    drag.x = e.clientX;
    drag.y = e.clientY;
    // Orbit: the eye turns about the look-at point, about the world's z
    // (left-right) and the camera's right (up-down).
    const c = state.camera = cameraFromForm();
    const look = add(c.eye, scale(c.forward, c.dist));
    const a = -dx * 0.01, b = dy * 0.01;
    let off = sub(c.eye, look);
    off = [off[0] * Math.cos(a) - off[1] * Math.sin(a), off[0] * Math.sin(a) + off[1] * Math.cos(a), off[2]];
    const right = norm(cross(scale(off, -1), [0, 0, 1]));
    const p = rotatePair(off, cross(right, norm(off)), b);
    off = scale(norm(p[0]), c.dist);
    c.eye = add(look, off);
    c.forward = norm(scale(off, -1));
    c.up = norm(cross(right, c.forward));
    orthonormalize(c);
    moved(true);
  });
  window.addEventListener('mouseup', (e) => {
    if (!drag)
      return;
    const wasDrag = drag.moved;
    drag = null;
    if (wasDrag) {
      render(false);
      return;
    }
    if (e.target === canvas && state.image)
      explainAt(e);
  });
  canvas.addEventListener('wheel', (e) => {
    e.preventDefault();
    const c = state.camera = cameraFromForm();
    const look = add(c.eye, scale(c.forward, c.dist));
    c.dist = Math.max(1e-3, c.dist * (e.deltaY > 0 ? 1.1 : 1 / 1.1));
    c.eye = sub(look, scale(c.forward, c.dist));
    moved(false);
  }, { passive: false });

  async function explainAt(e) {
    // The image's pixel under the pointer, within the canvas's border.
    const r = canvas.getBoundingClientRect();
    const x = Math.min(canvas.width - 1, Math.floor((e.clientX - r.left - canvas.clientLeft) * canvas.width / canvas.clientWidth));
    const y = Math.min(canvas.height - 1, Math.floor((e.clientY - r.top - canvas.clientTop) * canvas.height / canvas.clientHeight));
    await explainPixel(x, y);
  }

  async function explainPixel(x, y) {
    const o = options(false);
    $('explain').replaceChildren(el('p', {}, 'explaining pixel ' + x + ',' + y + '...'));
    try {
      const ex = await whitted.explain(scene(), x, y, o);
      showExplanation(ex, $('explain'));
      document.body.dataset.explained = String(Number(document.body.dataset.explained || 0) + 1);
    } catch (err) {
      $('explain').replaceChildren(el('p', {}, err.message));
    }
  }

  render(false);
})();
