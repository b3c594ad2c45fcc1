// ray1 explore: the page a student uses to point at a wrong pixel and read its story.
// It talks to ray.inspect.ExploreServer through the JSON API (api/scene, api/trace, api/rerender,
// the three PNGs); every URL is relative so the page works under any port or prefix.
'use strict';

// ---------------------------------------------------------------------------------------------
// State

const state = {
  scene: null,          // the last answer of api/scene or api/rerender
  zoom: 1,
  selected: null,       // {x, y}: the pixel whose trace is shown (or on its way)
  trace: null,          // the last trace received, drawn in the views
  traceSeq: 0,          // numbers trace requests, so a slow answer for an old pixel is dropped
  traceTimer: null,     // arrow keys repeat fast: wait a moment before asking the server
  zoomFromUrl: null,
  // Errors of the API, one slot per kind of request, so a successful request clears only its own.
  errors: { scene: null, rerender: null, trace: null, image: null, address: null, unexpected: null },
  rendering: false,
};

const IMAGE_IDS = ['render', 'reference', 'diff'];
const MAX_DEFAULT_ZOOM = 4;
const FIT_WIDTH_PX = 600;
const ARROW_DELAY_MS = 120;
const DIFFERENCE_ALLOWED = 2; // levels per channel, as the render tests and the heat map count them
const SVG_NS = 'http://www.w3.org/2000/svg';

const $ = (id) => document.getElementById(id);

// ---------------------------------------------------------------------------------------------
// Numbers, formatted as `ray1 trace` prints them (ray.inspect.Fmt), so the page and the CLI agree
// digit for digit: six significant digits, no trailing zeros, whole numbers without a point.

function fmtNum(x) {
  // The API sends null where the value was NaN or infinite; for a distance that means ∞.
  if (x === null || x === undefined) return '∞';
  if (typeof x !== 'number' || Number.isNaN(x)) return 'NaN';
  if (!Number.isFinite(x)) return x > 0 ? '∞' : '−∞';
  if (x === 0) return '0';
  if (Number.isInteger(x) && Math.abs(x) < 1e9) return String(x);
  const magnitude = Math.abs(x);
  if (magnitude >= 1e-4 && magnitude < 1e9) {
    const s = x.toPrecision(6);
    // Java's %.6g switches to an exponent from 10⁶ on and keeps its zeros there.
    return s.includes('e') ? javaExponent(s) : stripZeros(s);
  }
  return javaExponent(x.toExponential(5)).replace(/\.?0+e/, 'e');
}

/** JavaScript writes 1e+6, Java 1e+06: pad the exponent to two digits. */
function javaExponent(s) {
  return s.replace(/e([+-])(\d)$/, (_, sign, digit) => `e${sign}0${digit}`);
}

function stripZeros(s) {
  if (!s.includes('.')) return s;
  return s.replace(/0+$/, '').replace(/\.$/, '');
}

/** A value that comes with a preformatted "…Text" twin: the twin wins (it says ∞ or NaN). */
function fmtText(text, value) {
  return text !== null && text !== undefined ? String(text) : fmtNum(value);
}

function fmtVec(v) {
  return Array.isArray(v) ? `(${v.map(fmtNum).join(', ')})` : '—';
}

function fmtRgb8(c) {
  return Array.isArray(c) ? c.join(', ') : '—';
}

function fmtMillis(ms) {
  if (typeof ms !== 'number') return '?';
  return ms < 1000 ? `${Math.round(ms)} ms` : `${fmtNum(Math.round(ms / 10) / 100)} s`;
}

function firstLine(text) {
  return String(text || '').trim().split(/\r?\n/)[0];
}

// ---------------------------------------------------------------------------------------------
// DOM helpers

/** el('div', {class: 'x'}, child, 'text', …): children may be nodes, strings, arrays or null. */
function el(tag, attrs, ...children) {
  const node = document.createElement(tag);
  setAttrs(node, attrs);
  appendAll(node, children);
  return node;
}

function svgEl(tag, attrs, ...children) {
  const node = document.createElementNS(SVG_NS, tag);
  setAttrs(node, attrs);
  appendAll(node, children);
  return node;
}

function setAttrs(node, attrs) {
  for (const [key, value] of Object.entries(attrs || {})) {
    if (value === null || value === undefined || value === false) continue;
    if (key === 'class') node.setAttribute('class', value);
    else node.setAttribute(key, String(value));
  }
}

function appendAll(node, children) {
  for (const child of children.flat(Infinity)) {
    if (child === null || child === undefined || child === false) continue;
    node.append(child instanceof Node ? child : String(child));
  }
}

// ---------------------------------------------------------------------------------------------
// The API

class ApiError extends Error {
  constructor(status, message) {
    super(message);
    this.status = status;
  }
}

/** Fetches JSON; any failure (network, HTTP error, not JSON) becomes an ApiError with one line. */
async function api(path, options = {}) {
  let response;
  try {
    response = await fetch(path, { cache: 'no-store', ...options });
  } catch (e) {
    throw new ApiError(0, `cannot reach the explore server (${e.message}); is it still running?`);
  }
  let body;
  try {
    body = await response.text();
  } catch (e) {
    throw new ApiError(response.status, `the answer to ${path} broke off (${e.message})`);
  }
  if (!response.ok) throw new ApiError(response.status, errorMessage(response.status, body));
  try {
    return JSON.parse(body);
  } catch (e) {
    throw new ApiError(response.status, `the answer to ${path} is not JSON: ${firstLine(body)}`);
  }
}

/** api/rerender answers 400 with {"error": …}; the other errors are one line of text. */
function errorMessage(status, body) {
  try {
    const parsed = JSON.parse(body);
    if (parsed && typeof parsed.error === 'string') return parsed.error;
  } catch (e) {
    // not JSON: the one-line text below is the message
  }
  return firstLine(body) || `HTTP ${status}`;
}

// ---------------------------------------------------------------------------------------------
// Scene, header and status

async function loadScene() {
  try {
    const scene = await api('api/scene');
    state.errors.scene = null;
    applyScene(scene, true);
    selectFromUrl();
  } catch (e) {
    state.errors.scene = `Cannot load the scene: ${e.message}`;
    renderStatus();
  }
}

function applyScene(scene, first) {
  state.scene = scene;
  document.title = `${scene.name || scene.scene} — ray1 explore`;
  $('scene-label').textContent = `${scene.scene} — ${scene.width}×${scene.height} pixels`;
  if (first) setZoom(state.zoomFromUrl || defaultZoom(scene.width), false);
  updateImages();
  renderReferenceSummary();
  renderStatus();
  keepSelectionInside();
  drawViews();
}

/** The largest zoom up to 4× at which the image still fits in about 600 CSS pixels. */
function defaultZoom(width) {
  let zoom = 1;
  for (let z = 2; z <= MAX_DEFAULT_ZOOM; z++) {
    if (width * z <= FIT_WIDTH_PX) zoom = z;
  }
  return zoom;
}

function renderStatus() {
  const box = $('status');
  const scene = state.scene;
  const lines = [];
  if (state.rendering) {
    lines.push(el('div', { class: 'line' }, 'Rendering…'));
  } else if (scene && scene.renderError != null) {
    lines.push(el('div', { class: 'line error' }, `The render failed: ${scene.renderError}`));
  } else if (scene) {
    lines.push(el('div', { class: 'line' }, `Rendered in ${fmtMillis(scene.renderMillis)} (render #${scene.renderId}).`));
  }
  for (const message of Object.values(state.errors)) {
    if (message) lines.push(el('div', { class: 'line error' }, message));
  }
  for (const note of (scene && scene.notes) || []) {
    lines.push(el('div', { class: 'line warning' }, `⚠ ${note}`));
  }
  box.replaceChildren(...lines);
}

function renderReferenceSummary() {
  const box = $('reference-summary');
  const ref = state.scene.reference;
  box.hidden = !ref;
  if (!ref) return;
  box.className = `reference-summary ${ref.passed ? 'pass' : 'fail'}`;
  const verdict = ref.passed ? 'PASS' : 'FAIL';
  box.replaceChildren(
    el('strong', { class: 'verdict' }, verdict),
    ` against ${ref.file}: `,
    el('span', { class: 'num' }, ref.summary || ''),
  );
  if (ref.sameSize === false) {
    box.append(el('span', { class: 'error' }, ' — the sizes differ, so there is no difference map.'));
  }
}

async function rerender() {
  if (state.rendering) return;
  const button = $('rerender');
  button.disabled = true;
  state.rendering = true;
  renderStatus();
  try {
    const scene = await api('api/rerender', { method: 'POST' });
    state.errors.rerender = null;
    state.rendering = false;
    applyScene(scene, false);
    if (state.selected) loadTrace();
  } catch (e) {
    // The previous render stays on the server, so the old images stay here too.
    state.rendering = false;
    state.errors.rerender = `Re-render failed: ${e.message}`;
    renderStatus();
  } finally {
    button.disabled = false;
  }
}

// ---------------------------------------------------------------------------------------------
// Images, zoom and the selection marker

function updateImages() {
  const scene = state.scene;
  const id = encodeURIComponent(scene.renderId);
  const failed = scene.renderError != null;
  // A failed render has no image: its error stands where the picture would be.
  $('render').closest('.frame').hidden = failed;
  $('render-error').hidden = !failed;
  $('render-error').textContent = failed ? `No image: ${scene.renderError}` : '';
  if (!failed) setImageSource('render', `api/image.png?r=${id}`);

  const ref = scene.reference;
  $('figure-reference').hidden = !ref;
  if (ref) setImageSource('reference', `api/reference.png?r=${id}`);
  const diffShown = Boolean(ref) && ref.sameSize !== false;
  $('figure-diff').hidden = !diffShown;
  if (diffShown) setImageSource('diff', `api/diff.png?r=${id}`);
  applyZoom();
}

function setImageSource(id, url) {
  const img = $(id);
  if (img.getAttribute('src') !== url) img.src = url;
}

/** An <img> cannot read the server's error line, so ask again with fetch to show it. */
async function reportImageError(img) {
  const url = img.getAttribute('src');
  if (!url) return;
  let message = 'it could not be loaded';
  try {
    const response = await fetch(url, { cache: 'no-store' });
    if (!response.ok) message = firstLine(await response.text()) || `HTTP ${response.status}`;
  } catch (e) {
    message = `cannot reach the explore server (${e.message})`;
  }
  state.errors.image = `${img.alt}: ${message}`;
  renderStatus();
}

function setZoom(zoom, byUser) {
  state.zoom = Math.min(8, Math.max(1, Math.round(zoom) || 1));
  $('zoom').value = String(state.zoom);
  if (byUser) {
    applyZoom();
    updateUrl();
  }
}

/** Sizes every image to zoom × its pixels; the reference may differ in size, so it uses its own. */
function applyZoom() {
  const scene = state.scene;
  if (!scene) return;
  for (const id of IMAGE_IDS) {
    const img = $(id);
    const own = id === 'reference' && img.complete && img.naturalWidth > 0;
    const width = own ? img.naturalWidth : scene.width;
    const height = own ? img.naturalHeight : scene.height;
    img.style.width = `${width * state.zoom}px`;
    img.style.height = `${height * state.zoom}px`;
  }
  $('render-error').style.width = `${scene.width * state.zoom}px`;
  $('render-error').style.height = `${scene.height * state.zoom}px`;
  placeMarkers();
}

function placeMarkers() {
  const sel = state.selected;
  const zoom = state.zoom;
  for (const marker of document.querySelectorAll('.frame .marker')) {
    marker.hidden = !sel;
    if (!sel) continue;
    // The marker's border sits just outside the pixel so the pixel itself stays visible.
    marker.style.left = `${sel.x * zoom - 1}px`;
    marker.style.top = `${sel.y * zoom - 1}px`;
    marker.style.width = `${zoom + 2}px`;
    marker.style.height = `${zoom + 2}px`;
  }
}

/** The pixel under a mouse event on one of the images, clamped to the render's size. */
function pixelAt(event) {
  const rect = event.currentTarget.getBoundingClientRect();
  const ox = event.clientX - rect.left;
  const oy = event.clientY - rect.top;
  return clampPixel(Math.floor(ox / state.zoom), Math.floor(oy / state.zoom));
}

function clampPixel(x, y) {
  const scene = state.scene;
  return {
    x: Math.min(scene.width - 1, Math.max(0, x)),
    y: Math.min(scene.height - 1, Math.max(0, y)),
  };
}

function onImageClick(event) {
  if (!state.scene) return;
  const { x, y } = pixelAt(event);
  select(x, y, 0);
}

function onImageHover(event) {
  if (!state.scene) return;
  const { x, y } = pixelAt(event);
  $('hover-pixel').textContent = `pointer at x = ${x}, y = ${y}`;
}

function select(x, y, delayMs) {
  const pixel = clampPixel(x, y);
  state.selected = pixel;
  placeMarkers();
  updateUrl();
  clearTimeout(state.traceTimer);
  if (delayMs > 0) state.traceTimer = setTimeout(loadTrace, delayMs);
  else loadTrace();
}

/** After a re-render the scene may have shrunk: keep the selected pixel on the image. */
function keepSelectionInside() {
  if (state.selected) {
    state.selected = clampPixel(state.selected.x, state.selected.y);
    updateUrl();
  }
  placeMarkers();
}

function onKeyDown(event) {
  if (!state.selected || !state.scene) return;
  if (event.altKey || event.ctrlKey || event.metaKey) return;
  // Arrows belong to the zoom list (and any text field) while it has the focus.
  const tag = event.target && event.target.tagName;
  if (tag === 'SELECT' || tag === 'INPUT' || tag === 'TEXTAREA') return;
  const step = event.shiftKey ? 10 : 1;
  const moves = { ArrowLeft: [-step, 0], ArrowRight: [step, 0], ArrowUp: [0, -step], ArrowDown: [0, step] };
  const move = moves[event.key];
  if (!move) return;
  event.preventDefault();
  select(state.selected.x + move[0], state.selected.y + move[1], ARROW_DELAY_MS);
}

// ---------------------------------------------------------------------------------------------
// The address: ?x=&y= selects a pixel on load (a link to a pixel); ?zoom= picks the zoom.

function readUrl() {
  const params = new URLSearchParams(window.location.search);
  const zoom = params.get('zoom');
  if (zoom !== null && /^[1-8]$/.test(zoom)) state.zoomFromUrl = Number(zoom);
}

function selectFromUrl() {
  const params = new URLSearchParams(window.location.search);
  const x = params.get('x');
  const y = params.get('y');
  if (x === null && y === null) return;
  const whole = /^\d+$/;
  if (x === null || y === null || !whole.test(x) || !whole.test(y)) {
    state.errors.address = `The address asks for pixel x = ${x}, y = ${y}: both must be whole numbers from 0.`;
    renderStatus();
    return;
  }
  select(Number(x), Number(y), 0);
}

function updateUrl() {
  const params = new URLSearchParams(window.location.search);
  if (state.selected) {
    params.set('x', String(state.selected.x));
    params.set('y', String(state.selected.y));
  }
  if (state.scene && state.zoom !== defaultZoom(state.scene.width)) params.set('zoom', String(state.zoom));
  else params.delete('zoom');
  const query = params.toString();
  // replaceState: moving the selection should not fill the back button's history.
  history.replaceState(null, '', query ? `?${query}` : window.location.pathname);
  state.errors.address = null;
}

// ---------------------------------------------------------------------------------------------
// The trace panel

async function loadTrace() {
  const sel = state.selected;
  if (!sel) return;
  const seq = ++state.traceSeq;
  $('trace').dataset.state = 'loading';
  try {
    const trace = await api(`api/trace?x=${sel.x}&y=${sel.y}`);
    if (seq !== state.traceSeq) return; // a newer pixel was chosen meanwhile
    state.trace = trace;
    renderTrace(trace);
    state.errors.trace = null;
    $('trace').dataset.state = 'ready';
  } catch (e) {
    if (seq !== state.traceSeq) return;
    state.trace = null;
    renderSelectedSummary(null);
    state.errors.trace = `Trace of x = ${sel.x}, y = ${sel.y}: ${e.message}`;
    // Leave nothing of the previous pixel on screen: it would read as this pixel's story.
    $('trace').dataset.state = 'error';
    $('trace-pixel').textContent = `x = ${sel.x}, y = ${sel.y}`;
    $('trace-head').hidden = true;
    $('trace-full').hidden = true;
    $('trace-body').replaceChildren(el('p', { class: 'error' }, e.message));
  }
  renderStatus();
  drawViews();
}

function renderTrace(t) {
  const traceBox = $('trace');
  traceBox.dataset.x = String(t.x);
  traceBox.dataset.y = String(t.y);
  $('trace-hint').hidden = true;
  $('trace-head').hidden = false;
  $('trace-pixel').textContent = `x = ${t.x}, y = ${t.y}`;
  renderPixelValues(t.value, t.reference);
  $('trace-body').replaceChildren(
    pixelSection(t),
    cameraRaySection(t.cameraRay),
    hitsSection(t.hits),
    closestSection(t),
    lightsSection(t.lights),
    shadingSection(t.shading),
  );
  $('trace-text').textContent = t.trace || '';
  $('trace-full').hidden = false;
  renderSelectedSummary(t);
}

/** One line in the (sticky) header: the pixel's value where the student is looking, and a way down. */
function renderSelectedSummary(t) {
  const box = $('selected-pixel');
  if (!t) {
    box.textContent = '';
    return;
  }
  const reference = Array.isArray(t.reference) ? ` (reference ${fmtRgb8(t.reference)})` : '';
  const differs = largestDifference(t.value, t.reference) > DIFFERENCE_ALLOWED;
  box.replaceChildren(
    el('span', { class: 'num' }, `x = ${t.x}, y = ${t.y}: `),
    el('span', { class: differs ? 'num differs' : 'num' }, `${fmtRgb8(t.value)}${reference}`),
    el('a', { href: '#trace' }, 'trace ↓'),
  );
}

/** The 8-bit value beside the reference's; both are marked when some channel differs by > 2. */
function renderPixelValues(value, reference) {
  $('trace-value').textContent = fmtRgb8(value);
  $('trace-reference').textContent = reference ? fmtRgb8(reference) : '—';
  setSwatch($('trace-value-swatch'), value);
  setSwatch($('trace-reference-swatch'), reference);
  const off = largestDifference(value, reference);
  const differs = off > DIFFERENCE_ALLOWED;
  $('trace-value').classList.toggle('differs', differs);
  $('trace-reference').classList.toggle('differs', differs);
  $('trace-value').title = differs ? `differs from the reference by up to ${off} levels` : '';
  $('trace-reference').title = $('trace-value').title;
}

/** The largest channel difference of two 8-bit colors; 0 when one is missing. */
function largestDifference(value, reference) {
  if (!Array.isArray(value) || !Array.isArray(reference)) return 0;
  return Math.max(...value.map((c, k) => Math.abs(c - reference[k])));
}

function setSwatch(swatch, rgb) {
  swatch.hidden = !Array.isArray(rgb);
  if (Array.isArray(rgb)) swatch.style.background = `rgb(${rgb.join(',')})`;
}

/** A two-column table of label and value; rows with a null value are left out. */
function kv(rows) {
  const grid = el('div', { class: 'kv' });
  for (const [label, value, cls] of rows) {
    if (value === null || value === undefined) continue;
    grid.append(el('span', { class: 'k' }, label), el('span', { class: `v num ${cls || ''}`.trim() }, value));
  }
  return grid;
}

function section(title, ...content) {
  return el('div', { class: 'trace-section' }, el('h3', {}, title), content);
}

function pixelSection(t) {
  // valueError (beyond API.md, sent by the server): the renderer threw, so the pixel has no value.
  const valueError = t.valueError ? el('p', { class: 'error' }, `! ${t.valueError}`) : null;
  return el('div', {}, valueError, kv([
    ['(i, j)', `(${t.i}, ${t.j})`],
    ['(u, v)', `(${fmtNum(t.u)}, ${fmtNum(t.v)})`],
    ['radiance', fmtVec(t.radiance)],
    ['samples', t.samples === undefined || t.samples === null ? null : String(t.samples)],
  ]));
}

function cameraRaySection(ray) {
  if (!ray) return section('Camera ray', el('p', { class: 'muted' }, 'none'));
  const hasRay = Array.isArray(ray.origin) || Array.isArray(ray.direction);
  return section('Camera ray',
    kv([
      ['call', ray.call || null],
      ['origin', hasRay ? fmtVec(ray.origin) : null],
      ['direction', hasRay ? fmtVec(ray.direction) : null],
      ['segment', hasRay ? `t from ${fmtText(ray.startText, ray.start)} to ${fmtText(ray.endText, ray.end)}` : null],
    ]),
    ray.error ? el('p', { class: 'error' }, `! ${ray.error}`) : null,
    ray.problem ? el('p', { class: 'error' }, `! ${ray.problem}`) : null,
  );
}

function hitsSection(hits) {
  if (!Array.isArray(hits) || hits.length === 0) {
    return section('Surfaces tested', el('p', { class: 'muted' }, 'the scene has no surfaces'));
  }
  return section('Surfaces tested', el('ul', { class: 'hits' }, hits.map(hitItem)));
}

/** One surface's line; groups, meshes and boxes fold their children into a <details>. */
function hitItem(h) {
  const children = Array.isArray(h.children) ? h.children : [];
  const classes = ['hit-entry'];
  if (h.nearest) classes.push('nearest');
  if (h.error || (h.problems && h.problems.length)) classes.push('has-problem');
  const item = el('li', { class: classes.join(' ') });
  if (children.length === 0) {
    item.append(hitLine(h));
  } else {
    const inside = [];
    const summarySaysNearest = typeof h.summary === 'string' && h.summary.includes('nearest');
    if (!h.nearest && !summarySaysNearest && children.some(containsNearest)) inside.push(el('span', { class: 'tag tag-nearest' }, 'nearest inside'));
    if (children.some(containsProblem)) inside.push(el('span', { class: 'tag tag-problem' }, 'problems inside'));
    const details = el('details', {}, el('summary', {}, hitLine(h, h.summary), inside));
    // A mesh may list thousands of triangles: build them only when the student opens the entry.
    details.addEventListener('toggle', () => {
      if (details.open && !details.querySelector('ul')) details.append(el('ul', { class: 'hits' }, children.map(hitItem)));
    });
    item.append(details);
  }
  if (h.error) item.append(el('div', { class: 'error' }, `! ${h.error}`));
  for (const problem of h.problems || []) item.append(el('div', { class: 'error' }, `! ${problem}`));
  return item;
}

function hitLine(h, summary) {
  const parts = [el('span', { class: 'path' }, h.path)];
  parts.push(el('span', { class: `tag ${h.hit ? 'tag-hit' : 'tag-miss'}` }, h.hit ? 'hit' : 'miss'));
  if (h.nearest) parts.push(el('span', { class: 'tag tag-nearest' }, 'nearest'));
  if (summary) parts.push(' ', el('span', { class: 'summary-text' }, summary));
  // A group, mesh or box has no t of its own: its summary names its nearest hit.
  if (h.hit && !summary) {
    parts.push(' ', el('span', { class: 'num' },
      `t = ${fmtText(h.tText, h.t)}`,
      Array.isArray(h.location) ? ` at ${fmtVec(h.location)}` : '',
      Array.isArray(h.normal) ? `, normal ${fmtVec(h.normal)}` : ''));
  }
  return el('span', { class: 'hit-line' }, parts);
}

function containsNearest(h) {
  return Boolean(h.nearest) || (h.children || []).some(containsNearest);
}

function containsProblem(h) {
  return Boolean(h.error) || (h.problems || []).length > 0 || (h.children || []).some(containsProblem);
}

function closestSection(t) {
  const parts = [];
  if (t.closestError) parts.push(el('p', { class: 'error' }, `! ${t.closestError}`));
  const c = t.closest;
  if (c) {
    parts.push(kv([
      ['surface', c.path],
      ['t', fmtText(c.tText, c.t)],
      ['location', fmtVec(c.location)],
      ['normal', fmtVec(c.normal)],
      ['shader', c.shader || null],
    ]));
    for (const flag of c.recordChecks || []) parts.push(el('p', { class: 'error' }, `! ${flag}`));
    if (c.check) parts.push(el('p', { class: c.check.startsWith('!') ? 'error' : 'ok' }, c.check));
  } else if (!t.closestError) {
    const background = Array.isArray(t.background) ? ` ${fmtVec(t.background)}` : '';
    parts.push(el('p', { class: 'num' }, `none: background${background}`));
  }
  return section('Closest hit', parts);
}

function lightsSection(lights) {
  if (!Array.isArray(lights) || lights.length === 0) {
    return section('Lights', el('p', { class: 'muted' }, 'no light is evaluated (nothing is hit, or the scene has no lights)'));
  }
  return section('Lights', lights.map(lightBlock));
}

function lightBlock(light) {
  const ray = light.shadowRay;
  const shadow = ray
    ? `origin ${fmtVec(ray.origin)}, direction ${fmtVec(ray.direction)}, t from ${fmtText(ray.startText, ray.start)} to ${fmtText(ray.endText, ray.end)}`
    : 'none';
  let blocked = null;
  if (light.blocked && light.blocker) {
    const b = light.blocker;
    blocked = el('span', { class: 'error' }, `blocked by ${b.path} at t = ${fmtText(b.tText, b.t)}`,
      Array.isArray(b.location) ? ` ${fmtVec(b.location)}` : '', b.check ? ` (! ${b.check})` : '');
  } else if (light.blocked) {
    blocked = el('span', { class: 'error' }, 'blocked');
  } else if (ray) {
    blocked = el('span', { class: 'ok' }, 'not blocked');
  }
  return el('div', { class: `light ${light.blocked ? 'light-blocked' : ''}`.trim() },
    el('h4', { class: 'num' }, `Light ${light.number} at ${fmtVec(light.position)}, intensity ${fmtVec(light.intensity)}`),
    kv([
      ['l', fmtVec(light.l)],
      ['r', fmtText(light.rText, light.r)],
      ['n·l', fmtText(light.nDotLText, light.nDotL)],
      ['shadow ray', shadow],
      ['', blocked],
      // shadowError (beyond API.md): the scene's group threw, or disagrees with the surfaces tested alone.
      ['', light.shadowError ? el('span', { class: 'error' }, `! ${light.shadowError}`) : null],
      ['diffuse', light.diffuse ? fmtVec(light.diffuse) : '—'],
      ['specular', light.specular ? fmtVec(light.specular) : '—'],
      // microfacet: the microfacet BRDF's factors as the shader's own classes compute them.
      ...(light.microfacet ? [
        ['F', light.microfacet.error ? el('span', { class: 'error' }, `! ${light.microfacet.error}`) : fmtNum(light.microfacet.fresnel)],
        ['D', fmtNum(light.microfacet.distribution)],
        ['G1(l), G1(v)', `${fmtNum(light.microfacet.maskingL)}, ${fmtNum(light.microfacet.maskingV)}`],
      ] : []),
      ['adds', fmtVec(light.adds)],
      // agreesWithFormula false: the shader's own shade (a student's light loop) differs from the formula's share.
      ['', light.agreesWithFormula === false
        ? el('span', { class: 'error' }, `✗ not the formula's ${fmtVec(light.formula)}: the shader's shade returns another value for this light`)
        : null],
    ]),
  );
}

function shadingSection(shading) {
  if (!shading) return section('Shading', el('p', { class: 'muted' }, 'none'));
  return section('Shading', kv([
    ['shader', shading.shader || null],
    ['total', fmtVec(shading.total)],
  ]));
}

// ---------------------------------------------------------------------------------------------
// The two views: the scene drawn orthographically from above and from the side, with the traced
// rays on top, so a student sees where the camera ray went and what it met.

const VIEW_SIZE = 320;
const VIEW_MARGIN = 24;

// Each view maps a world point to (right, up) on the drawing. Looking down −y with x to the
// right puts z toward the bottom; looking along −x with y up puts z toward the left.
const VIEWS = [
  {
    id: 'view-top',
    project: (p) => [p[0], -p[2]],
    axes: { origin: [16, 16], first: { dx: 1, dy: 0, label: 'x' }, second: { dx: 0, dy: 1, label: 'z' } },
    frustumAxis: 'u',
    frustumSize: 'viewWidth',
  },
  {
    id: 'view-side',
    project: (p) => [-p[2], p[1]],
    axes: { origin: [46, VIEW_SIZE - 16], first: { dx: -1, dy: 0, label: 'z' }, second: { dx: 0, dy: -1, label: 'y' } },
    frustumAxis: 'v',
    frustumSize: 'viewHeight',
  },
];

const vAdd = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
const vSub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const vScale = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
const vLength = (a) => Math.hypot(a[0], a[1], a[2]);
const isVec = (a) => Array.isArray(a) && a.length === 3 && a.every((c) => typeof c === 'number');

function vUnit(a) {
  const length = vLength(a);
  return length > 0 ? vScale(a, 1 / length) : null;
}

/** World bounds → a drawing transform with the same scale on both axes, centered. */
function makeFit(view, bounds) {
  const corners = boxCorners(bounds.min, bounds.max).map(view.project);
  const xs = corners.map((c) => c[0]);
  const ys = corners.map((c) => c[1]);
  const [minX, maxX, minY, maxY] = [Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)];
  const inner = VIEW_SIZE - 2 * VIEW_MARGIN;
  const spanX = maxX - minX;
  const spanY = maxY - minY;
  const span = Math.max(spanX, spanY);
  const scale = span > 0 ? inner / span : 1;
  const midX = (minX + maxX) / 2;
  const midY = (minY + maxY) / 2;
  const toScreen = (p) => {
    const [r, u] = view.project(p);
    return [VIEW_SIZE / 2 + (r - midX) * scale, VIEW_SIZE / 2 - (u - midY) * scale];
  };
  const diagonal = vLength(vSub(bounds.max, bounds.min)) || 1;
  return { toScreen, scale, diagonal };
}

function boxCorners(min, max) {
  const corners = [];
  for (let k = 0; k < 8; k++) {
    corners.push([(k & 1 ? max : min)[0], (k & 2 ? max : min)[1], (k & 4 ? max : min)[2]]);
  }
  return corners;
}

const r2 = (n) => Math.round(n * 100) / 100;
const pt = (p) => `${r2(p[0])},${r2(p[1])}`;

function drawViews() {
  for (const view of VIEWS) {
    const svg = $(view.id);
    svg.replaceChildren();
    const scene = state.scene;
    if (!scene || !scene.bounds || !isVec(scene.bounds.min) || !isVec(scene.bounds.max)) continue;
    const fit = makeFit(view, scene.bounds);
    const closestPath = state.trace && state.trace.closest ? state.trace.closest.path : null;
    svg.append(
      arrowDefs(view.id),
      svgEl('rect', { class: 'view-bg', x: 0, y: 0, width: VIEW_SIZE, height: VIEW_SIZE }),
      axesGlyph(view.axes),
      svgEl('g', { class: 'surfaces' }, (scene.surfaces || []).map((s) => drawSurface(s, view, fit, closestPath))),
      drawCamera(scene.camera, view, fit),
      svgEl('g', { class: 'lights' }, (scene.lights || []).map((l, k) => drawLight(l, k, fit))),
      state.trace ? drawTraceRays(state.trace, view, fit) : null,
    );
  }
}

function arrowDefs(viewId) {
  return svgEl('defs', {},
    svgEl('marker', {
      id: `${viewId}-arrow`, viewBox: '0 0 10 10', refX: 9, refY: 5,
      markerWidth: 7, markerHeight: 7, orient: 'auto-start-reverse',
    }, svgEl('path', { class: 'arrow-head', d: 'M0,0 L10,5 L0,10 z' })));
}

/** Two little arrows in a corner naming the drawing's axes. */
function axesGlyph(axes) {
  const [ox, oy] = axes.origin;
  const length = 22;
  const arm = (a) => {
    const end = [ox + a.dx * length, oy + a.dy * length];
    const label = [ox + a.dx * (length + 8), oy + a.dy * (length + 8) + 4];
    return [
      svgEl('line', { class: 'axis', x1: ox, y1: oy, x2: end[0], y2: end[1] }),
      svgEl('path', { class: 'axis-head', d: arrowHeadPath(end, [a.dx, a.dy]) }),
      svgEl('text', { class: 'axis-label', x: label[0], y: label[1], 'text-anchor': 'middle' }, a.label),
    ];
  };
  return svgEl('g', { class: 'axes' }, arm(axes.first), arm(axes.second));
}

function arrowHeadPath(tip, dir) {
  const [dx, dy] = dir;
  const back = [tip[0] - dx * 6, tip[1] - dy * 6];
  const side = [-dy * 3.5, dx * 3.5];
  return `M${pt(tip)} L${pt([back[0] + side[0], back[1] + side[1]])} L${pt([back[0] - side[0], back[1] - side[1]])} Z`;
}

function drawSurface(s, view, fit, closestPath) {
  const nearest = closestPath !== null && typeof s.name === 'string'
    && (closestPath === s.name || closestPath.startsWith(s.name));
  const cls = `surface surface-${s.kind}${nearest ? ' nearest-surface' : ''}`;
  const title = svgEl('title', {}, s.name || s.kind);
  switch (s.kind) {
    case 'sphere':
      return drawCircle(s.center, s.radius, cls, title, fit);
    case 'triangle':
      return drawPolygons([s.vertices], cls, title, fit, 1);
    case 'mesh': {
      const triangles = Array.isArray(s.triangles) ? s.triangles : [];
      // Thousands of overlapping edges at full strength make a black blob: fade with their number.
      const opacity = Math.min(0.8, Math.max(0.05, 6 / Math.sqrt(Math.max(1, triangles.length))));
      if (s.truncated) title.textContent += ' (only the first triangles are drawn)';
      return drawPolygons(triangles, cls, title, fit, opacity);
    }
    case 'cylinder': {
      if (!isVec(s.center)) return null;
      const half = [s.radius, s.height / 2, s.radius];
      // The axis is along y: from above a circle, from the side a rectangle.
      return view.id === 'view-top'
        ? drawCircle(s.center, s.radius, cls, title, fit)
        : drawBox(vSub(s.center, half), vAdd(s.center, half), cls, title, fit);
    }
    case 'box':
    case 'other':
    default:
      return isVec(s.min) && isVec(s.max) ? drawBox(s.min, s.max, cls, title, fit) : null;
  }
}

function drawCircle(center, radius, cls, title, fit) {
  if (!isVec(center) || typeof radius !== 'number') return null;
  const [cx, cy] = fit.toScreen(center);
  return svgEl('circle', { class: cls, cx: r2(cx), cy: r2(cy), r: r2(Math.max(0.75, Math.abs(radius) * fit.scale)) }, title);
}

function drawBox(min, max, cls, title, fit) {
  const screen = boxCorners(min, max).map(fit.toScreen);
  const xs = screen.map((p) => p[0]);
  const ys = screen.map((p) => p[1]);
  const x = Math.min(...xs);
  const y = Math.min(...ys);
  return svgEl('rect', {
    class: cls, x: r2(x), y: r2(y),
    width: r2(Math.max(0.75, Math.max(...xs) - x)), height: r2(Math.max(0.75, Math.max(...ys) - y)),
  }, title);
}

/** All triangles of one surface as a single path: one element even for a 4000-triangle mesh. */
function drawPolygons(triangles, cls, title, fit, opacity) {
  let d = '';
  for (const tri of triangles) {
    if (!Array.isArray(tri) || tri.length < 3 || !tri.every(isVec)) continue;
    const [a, b, c] = tri.map(fit.toScreen);
    d += `M${pt(a)}L${pt(b)}L${pt(c)}Z`;
  }
  if (!d) return null;
  return svgEl('path', { class: cls, d, 'stroke-opacity': opacity < 1 ? r2(opacity) : null }, title);
}

function drawCamera(camera, view, fit) {
  if (!camera || !isVec(camera.viewPoint)) return null;
  const eye = camera.viewPoint;
  const group = svgEl('g', { class: 'camera' }, svgEl('title', {}, `camera (${camera.kind}) at ${fmtVec(eye)}`));
  group.append(...frustumLines(camera, view, fit));
  const [ex, ey] = fit.toScreen(eye);
  const dir = isVec(camera.viewDir) ? screenDirection(eye, camera.viewDir, fit) : null;
  if (dir) {
    // A small triangle pointing where the camera looks.
    const [dx, dy] = dir;
    const tip = [ex + dx * 9, ey + dy * 9];
    const back = [ex - dx * 5, ey - dy * 5];
    const side = [-dy * 5, dx * 5];
    group.append(svgEl('path', {
      class: 'camera-body',
      d: `M${pt(tip)}L${pt([back[0] + side[0], back[1] + side[1]])}L${pt([back[0] - side[0], back[1] - side[1]])}Z`,
    }));
  } else {
    group.append(svgEl('circle', { class: 'camera-body', cx: r2(ex), cy: r2(ey), r: 4.5 }));
  }
  return group;
}

/** The unit direction on the drawing of a world direction at a point, or null when it points at us. */
function screenDirection(from, direction, fit) {
  const a = fit.toScreen(from);
  const b = fit.toScreen(vAdd(from, vScale(vUnit(direction) || [0, 0, 0], 1)));
  const length = Math.hypot(b[0] - a[0], b[1] - a[1]);
  if (length < 1e-6 * Math.max(1, fit.scale)) return null;
  return [(b[0] - a[0]) / length, (b[1] - a[1]) / length];
}

/**
 * The two edges of the view frustum in this view's plane: through the middle of the image's left and
 * right edges (top view) or top and bottom edges (side view), as far as the scene's diagonal.
 */
function frustumLines(camera, view, fit) {
  const eye = camera.viewPoint;
  const axis = camera[view.frustumAxis];
  const half = (camera[view.frustumSize] || 0) / 2;
  const w = camera.w;
  if (!isVec(axis) || !isVec(w) || !(half > 0)) return [];
  const lines = [];
  const line = (a, b, cls) => {
    const [p, q] = [fit.toScreen(a), fit.toScreen(b)];
    lines.push(svgEl('line', { class: cls, x1: r2(p[0]), y1: r2(p[1]), x2: r2(q[0]), y2: r2(q[1]) }));
  };
  if (camera.kind === 'perspective' && typeof camera.projDistance === 'number') {
    const d = camera.projDistance;
    const corners = [-1, 1].map((sign) => vAdd(vScale(w, -d), vScale(axis, sign * half)));
    for (const c of corners) line(eye, vAdd(eye, vScale(vUnit(c), fit.diagonal)), 'frustum');
    // The image window itself, at projDistance in front of the eye.
    line(vAdd(eye, corners[0]), vAdd(eye, corners[1]), 'frustum-window');
  } else if (camera.kind === 'orthographic') {
    const forward = vScale(vUnit(w) || w, -fit.diagonal);
    for (const sign of [-1, 1]) {
      const start = vAdd(eye, vScale(axis, sign * half));
      line(start, vAdd(start, forward), 'frustum');
    }
    line(vAdd(eye, vScale(axis, -half)), vAdd(eye, vScale(axis, half)), 'frustum-window');
  }
  return lines;
}

function drawLight(light, index, fit) {
  if (!isVec(light.position)) return null;
  const [x, y] = fit.toScreen(light.position);
  return svgEl('circle', { class: 'light', cx: r2(x), cy: r2(y), r: 5 },
    svgEl('title', {}, `light ${index + 1} at ${fmtVec(light.position)}, intensity ${fmtVec(light.intensity)}`));
}

/** The traced pixel's rays: camera ray, hit point, normal, and one shadow ray per light. */
function drawTraceRays(trace, view, fit) {
  const group = svgEl('g', { class: 'trace-rays' });
  const ray = trace.cameraRay;
  if (!ray || !isVec(ray.origin) || !isVec(ray.direction)) return group;
  const closest = trace.closest && isVec(trace.closest.location) ? trace.closest : null;
  const segment = (a, b, attrs) => {
    const [p, q] = [fit.toScreen(a), fit.toScreen(b)];
    return svgEl('line', { x1: r2(p[0]), y1: r2(p[1]), x2: r2(q[0]), y2: r2(q[1]), ...attrs });
  };

  if (closest) {
    group.append(segment(ray.origin, closest.location, { class: 'camera-ray' }));
  } else {
    // Nothing is hit: show where the ray heads, as long as the scene is wide.
    const unit = vUnit(ray.direction);
    if (unit) group.append(segment(ray.origin, vAdd(ray.origin, vScale(unit, fit.diagonal)), { class: 'camera-ray miss' }));
    return group;
  }

  for (const light of trace.lights || []) {
    if (!light.shadowRay || !isVec(light.position)) continue;
    const from = isVec(light.shadowRay.origin) ? light.shadowRay.origin : closest.location;
    const line = segment(from, light.position, { class: `shadow-ray ${light.blocked ? 'blocked' : 'clear'}` });
    line.append(svgEl('title', {}, `shadow ray to light ${light.number}: ${light.blocked ? 'blocked' : 'not blocked'}`));
    group.append(line);
    if (light.blocked && light.blocker && isVec(light.blocker.location)) {
      group.append(blockerCross(fit.toScreen(light.blocker.location), light.blocker.path));
    }
  }

  if (isVec(closest.normal)) {
    const unit = vUnit(closest.normal);
    // 28 pixels on the drawing, as a world length, so the projection still shortens it honestly.
    if (unit) {
      group.append(segment(closest.location, vAdd(closest.location, vScale(unit, 28 / fit.scale)),
        { class: 'normal', 'marker-end': `url(#${view.id}-arrow)` }));
    }
  }
  const [hx, hy] = fit.toScreen(closest.location);
  group.append(svgEl('circle', { class: 'hit-point', cx: r2(hx), cy: r2(hy), r: 3.5 },
    svgEl('title', {}, `hit at ${fmtVec(closest.location)}`)));
  return group;
}

function blockerCross(center, path) {
  const [x, y] = center;
  const s = 5;
  return svgEl('g', { class: 'blocker' },
    svgEl('title', {}, `blocked by ${path}`),
    svgEl('line', { x1: r2(x - s), y1: r2(y - s), x2: r2(x + s), y2: r2(y + s) }),
    svgEl('line', { x1: r2(x - s), y1: r2(y + s), x2: r2(x + s), y2: r2(y - s) }));
}

// ---------------------------------------------------------------------------------------------
// Wiring

function wire() {
  for (const id of IMAGE_IDS) {
    const img = $(id);
    img.addEventListener('click', onImageClick);
    img.addEventListener('mousemove', onImageHover);
    img.addEventListener('mouseleave', () => { $('hover-pixel').textContent = ''; });
    img.addEventListener('load', () => {
      if (state.errors.image && state.errors.image.startsWith(`${img.alt}:`)) {
        state.errors.image = null;
        renderStatus();
      }
      if (id === 'reference') applyZoom(); // its own size is known only now
    });
    img.addEventListener('error', () => reportImageError(img));
  }
  $('zoom').addEventListener('change', (e) => setZoom(Number(e.target.value), true));
  $('rerender').addEventListener('click', rerender);
  document.addEventListener('keydown', onKeyDown);
}

// Anything that slips through still ends up on the page, not only in the console.
function reportUnexpected(error) {
  state.errors.unexpected = `Unexpected error in the page: ${error && error.message ? error.message : error}`;
  renderStatus();
}
window.addEventListener('unhandledrejection', (event) => reportUnexpected(event.reason));
window.addEventListener('error', (event) => reportUnexpected(event.error || event.message));

readUrl();
wire();
loadScene();
