/* The page's reports, drawn from the objects of window.whitted: the
 * explanation of a pixel (whitted explain --json) as a tree of rays, the
 * report of whitted compare (its --json object and difference picture),
 * and grade's table with its CSV. */
'use strict';

function el(tag, attrs, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) {
    if (k === 'class')
      e.className = v;
    else
      e.setAttribute(k, v);
  }
  for (const c of children)
    e.append(c instanceof Node ? c : document.createTextNode(String(c)));
  return e;
}

function fmt(v) {
  if (v === null || v === undefined)
    return '-';
  if (Array.isArray(v))
    return '(' + v.map(fmt).join(', ') + ')';
  return typeof v === 'number' ? String(Number(v.toPrecision(6))) : String(v);
}

function objectName(o) {
  if (!o)
    return 'an object';
  if (o.floor)
    return 'the floor';
  return 'object ' + o.index + ' (' + o.keyword + (o.line ? ', line ' + o.line : '') + ')';
}

function lightLine(l) {
  const head = 'light ' + l.index + ' at ' + fmt(l.position) + ': ';
  switch (l.state) {
  case 'lit':
    return head + 'N.L ' + fmt(l.n_dot_l) + ', R.L ' + fmt(l.r_dot_l) +
      (l.attenuation !== 1 ? ', falloff ' + fmt(l.attenuation) : '') +
      '; diffuse ' + fmt(l.diffuse) + ' + specular ' + fmt(l.specular) + ' = ' + fmt(l.term);
  case 'shadowed':
    return head + 'shadow ray blocked by ' + objectName(l.blocker);
  case 'behind':
    return head + 'behind the surface (N.L ' + fmt(l.n_dot_l) + ' <= 0)';
  case 'outside-cone':
    return head + "outside the spotlight's cone";
  default:
    return head + 'at the point';
  }
}

function rayDetails(ex, id) {
  const r = ex.rays[id];
  const title = 'ray ' + id + ': ' + r.kind + (ex.samples > 1 ? ' (sample ' + r.sample + ')' : '') +
    ', level ' + r.level + ' -> ' + fmt(r.color);
  const d = el('details', { open: '', 'data-ray': String(id) }, el('summary', {}, title));
  d.append(el('div', { class: 'num' }, 'from ' + fmt(r.origin) + ' along ' + fmt(r.direction)));
  if (!r.hit) {
    d.append(el('div', {}, 'hits nothing: black'));
    return d;
  }
  const h = r.hit;
  const ul = el('ul', {});
  ul.append(el('li', { class: 'hit' }, 'hits ' + objectName(h.object) + ' at t = ' + fmt(h.t)));
  ul.append(el('li', { class: 'num' }, 'point ' + fmt(h.point) + ', normal ' + fmt(h.normal) +
    (h.normal_turned ? ' (turned to face the ray)' : '')));
  ul.append(el('li', { class: 'num' }, 'colour C ' + fmt(h.surface) + '; ka ' + fmt(h.material.ka) +
    ' kd ' + fmt(h.material.kd) + ' ks ' + fmt(h.material.ks) + ' kr ' + fmt(h.material.kr) +
    ' shininess ' + fmt(h.material.shininess) + (h.material.kt > 0 ? ' kt ' + fmt(h.material.kt) : '')));
  ul.append(el('li', { class: 'num' }, 'ambient ka C = ' + fmt(h.ambient)));
  for (const l of h.lights)
    ul.append(el('li', { class: 'num light-' + l.state }, lightLine(l)));
  if (h.reflection)
    ul.append(el('li', { class: 'num' }, (h.total_internal_reflection ? 'total internal reflection ' : 'reflection kr ') +
      fmt(h.reflection.k) + ' x ray ' + h.reflection.ray + "'s " + fmt(h.reflection.color)));
  if (h.refraction)
    ul.append(el('li', { class: 'num' }, 'refraction kt ' + fmt(h.refraction.k) + ' x ray ' +
      h.refraction.ray + "'s " + fmt(h.refraction.color)));
  ul.append(el('li', { class: 'num' }, 'sum ' + fmt(h.sum) + (ex.clamp === 'level' ? ', clamped ' : ', returned ') + fmt(r.color)));
  d.append(ul);
  for (const c of [h.reflection, h.refraction])
    if (c)
      d.append(rayDetails(ex, c.ray));
  return d;
}

function showExplanation(ex, box) {
  box.replaceChildren(el('h2', {}, 'Pixel ' + ex.x + ',' + ex.y));
  box.append(el('p', { id: 'explain-value' }, '8-bit value (' + ex.value.join(', ') + '), from ' +
    fmt(ex.color) + ' clamped to ' + fmt(ex.clamped)));
  ex.rays.forEach((r, id) => {
    if (r.parent === null)
      box.append(rayDetails(ex, id));
  });
  if (ex.samples > 1)
    box.append(el('p', {}, ex.samples + 'x' + ex.samples + ' samples, each clamped and averaged: ' +
      ex.sample_colors.map(fmt).join(' ')));
}

function pngUrl(bytes) {
  return URL.createObjectURL(new Blob([bytes], { type: 'image/png' }));
}

function showCompare(res, box, imageName) {
  box.replaceChildren(el('h2', {}, 'Your image: ' + imageName));
  const verdict = res.verdict === 'match' ? 'MATCH' : 'DIFFERS';
  box.append(el('p', {}, 'verdict: ', el('span', { id: 'verdict', class: 'verdict-' + res.verdict }, verdict),
    ', PSNR ' + (res.psnr === null ? 'inf' : res.psnr.toFixed(2)) + ' dB'));
  if (res.size_note)
    box.append(el('p', {}, 'note: ' + res.size_note));
  if (res.camera && res.camera.moved)
    box.append(el('p', { id: 'found-camera' }, 'camera: yours differs; found ' + res.camera.options));
  box.append(el('p', { id: 'diagnosis' }, res.diagnosis));
  if (res.objects_line && res.verdict !== 'match')
    box.append(el('p', {}, 'objects: ' + res.objects_line));
  if (res.causes.length) {
    const t = el('table', { id: 'causes' }, el('tr', {}, el('th', {}, '#'), el('th', {}, 'likely cause'),
      el('th', {}, 'PSNR'), el('th', {}, 'fix')));
    res.causes.slice(0, 5).forEach((c, i) => {
      t.append(el('tr', { 'data-cause': c.id }, el('td', {}, String(i + 1)),
        el('td', {}, c.with + (c.explains ? ' (explains the image)' : '')),
        el('td', {}, c.psnr === null ? 'inf' : c.psnr.toFixed(2)), el('td', {}, c.fix)));
    });
    box.append(t);
  }
  if (res.objects.length && res.verdict !== 'match') {
    const t = el('table', { id: 'objects' }, el('tr', {}, el('th', {}, 'object'), el('th', {}, 'pixels'),
      el('th', {}, 'off by > 2'), el('th', {}, 'PSNR')));
    for (const o of res.objects)
      t.append(el('tr', {}, el('td', {}, (o.index === null ? '' : o.index + ' ') + o.keyword),
        el('td', {}, String(o.pixels)), el('td', {}, (100 * o.off2).toFixed(2) + '%'),
        el('td', {}, o.psnr === null ? 'inf' : o.psnr.toFixed(2))));
    box.append(t);
  }
  if (res.diff)
    box.append(el('p', {}, 'The difference (x8) beside where it differs:'), el('img', { id: 'diff', src: pngUrl(res.diff), alt: 'difference picture' }));
}

function showGrade(res, box) {
  box.replaceChildren(el('h2', {}, 'Grades'));
  const rows = res.csv.trim().split(/\r?\n/).map(parseCsvLine);
  const t = el('table', { id: 'grade-table' });
  rows.forEach((r, i) => t.append(el('tr', {}, ...r.map((c) => el(i ? 'td' : 'th', {}, c)))));
  box.append(t);
  const a = el('a', { id: 'csv-link', download: 'marks.csv', href: URL.createObjectURL(new Blob([res.csv], { type: 'text/csv' })) }, 'Download CSV');
  box.append(el('p', {}, a));
}

function parseCsvLine(line) {
  const out = [];
  let cur = '', q = false;
  for (let i = 0; i < line.length; i++) {
    const ch = line[i];
    if (q) {
      if (ch === '"' && line[i + 1] === '"') {
        cur += '"';
        i++;
      } else if (ch === '"') {
        q = false;
      } else {
        cur += ch;
      }
    } else if (ch === '"') {
      q = true;
    } else if (ch === ',') {
      out.push(cur);
      cur = '';
    } else {
      cur += ch;
    }
  }
  out.push(cur);
  return out;
}
