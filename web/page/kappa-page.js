// The kappa page: URL parameters, the mesh file (URL, file picker, drag and
// drop), mouse navigation, the settings panel (built from the settings table of
// app/appearance_settings.h that the wasm module hands over as JSON) and the
// PNG and SVG downloads. The drawing itself is web/src/page_api.cpp's.
//
// URL parameters (docs/web.md): mesh=URL view=AZ,EL size=WxH panel=off, and
// any appearance setting by its command-line name (lines=LIST shading=NAME ...). document.title says "kappa: ready" once the view
// asked for is drawn, "kappa: error: MESSAGE" when something failed.
'use strict';

const params = new URLSearchParams(window.location.search);
const canvas = document.getElementById('canvas');
const messageBox = document.getElementById('message');
let fixedSize = null;       // [w, h] from size=WxH
let meshName = 'kappa';     // for the names of downloads
let drawPending = false;
let readyWhenDrawn = false; // the title turns to ready after the next complete frame
let viewMoving = false;     // a drag or a zoom under way: frames keep the fields they have
// Seconds: open (read and prepare the mesh), draw (the last frame); preparations: the last
// view fields' preparations, each {slices, longest_ms, work_ms, wall_ms}.
const times = { preparations: [] };

function call(name, ...args) {
  const types = args.map(a => (typeof a === 'number' ? 'number' : 'string'));
  const status = Module.ccall(name, 'number', types, args);
  if (status !== 0) throw new Error(Module.ccall('kappa_message', 'string', [], []));
}

function showMessage(text, isError) {
  messageBox.textContent = text;
  messageBox.className = isError ? 'error' : '';
}

function fail(message) {
  // The same line as the command line prints ("kappa: NAME: problem").
  showMessage('kappa: ' + message, true);
  document.title = 'kappa: error: ' + message;
  readyWhenDrawn = false;
}

function requestDraw() {
  if (drawPending) return;
  drawPending = true;
  // A timer as well as a frame callback: whichever comes first draws (frame
  // callbacks do not run in some headless modes).
  const draw = () => {
    if (!drawPending) return;
    drawPending = false;
    try {
      const t0 = performance.now();
      call('kappa_draw');
      times.draw = (performance.now() - t0) / 1000;
      if (!Module.ccall('kappa_view_prepared', 'number', [], [])) {
        if (!viewMoving) prepareFields();
      } else if (readyWhenDrawn) {
        readyWhenDrawn = false;
        document.title = 'kappa: ready';
      }
    } catch (e) {
      fail(e.message);
    }
  };
  requestAnimationFrame(draw);
  setTimeout(draw, 50);
}

// --- the view's fields, prepared in slices ------------------------------------------
// The fields of a view at rest (with --detail, those of its scale) take a few
// hundred ms on a large mesh: the module works on them in slices of about
// sliceMs, each its own task, so that input and frames go on in between. A
// message to ourselves starts the next slice sooner than a timer would (no
// 4 ms clamp). Frames keep the fields they have until the new ones are done.

const sliceMs = 12;
const slices = new MessageChannel();
let preparation = null;  // the one under way: {slices, longest_ms, work_ms, started}

function prepareFields() {
  if (preparation) return;
  preparation = { slices: 0, longest_ms: 0, work_ms: 0, started: performance.now() };
  slices.port2.postMessage(0);
}

slices.port1.onmessage = () => {
  const p = preparation;
  if (!p) return;
  if (viewMoving) {  // the view moved on: prepared again when it rests
    preparation = null;
    return;
  }
  const t0 = performance.now();
  const status = Module.ccall('kappa_prepare', 'number', ['number'], [sliceMs]);
  const ms = performance.now() - t0;
  p.slices += 1;
  p.work_ms += ms;
  p.longest_ms = Math.max(p.longest_ms, ms);
  if (status === 2) {
    slices.port2.postMessage(0);
    return;
  }
  preparation = null;
  if (status === 1) {
    fail(Module.ccall('kappa_message', 'string', [], []));
    return;
  }
  times.preparations.push({ slices: p.slices, longest_ms: p.longest_ms, work_ms: p.work_ms,
                            wall_ms: performance.now() - p.started });
  if (times.preparations.length > 20) times.preparations.shift();
  requestDraw();
};

// --- size and layout -----------------------------------------------------------

function layout() {
  let w, h;
  if (fixedSize) {
    [w, h] = fixedSize;
  } else {
    const view = document.getElementById('view');
    w = Math.max(1, view.clientWidth);
    h = Math.max(1, view.clientHeight);
  }
  canvas.style.width = w + 'px';
  canvas.style.height = h + 'px';
  call('kappa_resize', w, h);
  requestDraw();
}

// --- opening meshes ------------------------------------------------------------

function baseName(path) {
  const name = decodeURIComponent(path.split(/[?#]/)[0].split('/').pop() || 'mesh');
  return name.replace(/[^A-Za-z0-9._+-]/g, '_');
}

// The buffers a .gltf names by URI (not data: URIs), where the reader looks
// for them: relative to the .gltf's folder, URI-decoded (as tinygltf does).
// Not JSON (or no buffers): none; the reader then says what is wrong.
function externalBuffers(name, bytes) {
  if (!/\.gltf$/i.test(name)) return [];
  let json;
  try {
    json = JSON.parse(new TextDecoder().decode(bytes));
  } catch (e) {
    return [];
  }
  const buffers = json && Array.isArray(json.buffers) ? json.buffers : [];
  return buffers.map(b => b && b.uri).filter(uri => typeof uri === 'string' && uri && !uri.startsWith('data:'))
    .map(uri => {
      let path = uri;
      try {
        path = decodeURIComponent(uri);
      } catch (e) {
        // not percent-encoded after all: as it is
      }
      return { uri, path };
    });
}

// Reads the mesh from bytes under its file name, as `kappa render NAME` would
// read the file; `beside`: the files next to it ({path, bytes}, paths relative
// to its folder: a .gltf's external buffers).
function openBytes(name, bytes, beside = []) {
  showMessage('reading ' + name + ' ...', false);
  document.title = 'kappa: loading';
  // Let the page show the message before the module computes (a few seconds for large meshes).
  return new Promise(resolve => setTimeout(resolve, 0)).then(() => {
    const written = ['/input/' + name];
    Module.FS.writeFile(written[0], bytes);
    try {
      for (const file of beside) {
        const path = '/input/' + file.path;
        Module.FS.mkdirTree(path.slice(0, path.lastIndexOf('/')));
        Module.FS.writeFile(path, file.bytes);
        written.push(path);
      }
      const t0 = performance.now();
      call('kappa_open', name);
      times.open = (performance.now() - t0) / 1000;
      meshName = name.replace(/\.[^.]*$/, '');
      showMessage(name, false);
      readyWhenDrawn = true;
      requestDraw();
      refreshPanel();
    } catch (e) {
      fail(e.message);
    } finally {
      for (const path of written) {
        try {
          Module.FS.unlink(path);
        } catch (e) {
          // written twice (a buffer named like the mesh): gone already
        }
      }
    }
  });
}

function openUrl(url) {
  const name = baseName(url);
  document.title = 'kappa: loading';
  const fetchBytes = (from, what) => fetch(from).then(r => {
    if (!r.ok) throw new Error(what + ': cannot read (HTTP ' + r.status + ')');
    return r.arrayBuffer();
  }).then(buffer => new Uint8Array(buffer));
  // A .gltf's external buffers come from next to it; one that cannot be
  // fetched is left out, and the reader says so as the command line does.
  const meshUrl = new URL(url, window.location.href);
  return fetchBytes(url, name)
    .then(bytes => Promise.all(externalBuffers(name, bytes).map(b =>
      fetchBytes(new URL(b.uri, meshUrl), b.path).then(data => ({ path: b.path, bytes: data }), () => null)))
      .then(beside => openBytes(name, bytes, beside.filter(Boolean))))
    .catch(e => fail(e.message.startsWith(name) ? e.message : name + ': cannot read (' + e.message + ')'));
}

const meshFormats = /\.(ply|obj|off|stl|gltf|glb)$/i;

// Files picked or dropped together: the first in a mesh format is opened,
// the others are the files beside it that it names (a .gltf's buffers, found
// by their file names).
function openFiles(list) {
  const files = Array.from(list);
  if (!files.length) return Promise.resolve();
  const mesh = files.find(f => meshFormats.test(f.name)) || files[0];
  return Promise.all(files.map(f => f.arrayBuffer().then(b => ({ name: f.name, bytes: new Uint8Array(b) }))))
    .then(read => {
      const main = read[files.indexOf(mesh)];
      const beside = [];
      for (const b of externalBuffers(main.name, main.bytes)) {
        const file = read.find(r => r !== main && r.name === b.path.split('/').pop());
        if (file) beside.push({ path: b.path, bytes: file.bytes });
      }
      return openBytes(baseName(main.name), main.bytes, beside);
    })
    .catch(e => fail(baseName(mesh.name) + ': cannot read (' + e.message + ')'));
}

// --- navigation ----------------------------------------------------------------

let drag = null;
let restTimer = 0;

function moving() {
  viewMoving = true;
  Module.ccall('kappa_moving', null, ['number'], [1]);
  clearTimeout(restTimer);
}

function rest(delay) {
  clearTimeout(restTimer);
  restTimer = setTimeout(() => {
    viewMoving = false;
    Module.ccall('kappa_moving', null, ['number'], [0]);
    requestDraw();  // which prepares the view's fields
  }, delay);
}

function canvasPoint(event) {
  const r = canvas.getBoundingClientRect();
  return [event.clientX - r.left, event.clientY - r.top];
}

canvas.addEventListener('pointerdown', event => {
  try {
    canvas.setPointerCapture(event.pointerId);  // drags continue outside the canvas
  } catch (e) {
    // a synthetic event's pointer cannot be captured
  }
  drag = { at: canvasPoint(event), pan: event.button !== 0 || event.shiftKey };
  moving();
});
canvas.addEventListener('pointermove', event => {
  if (!drag) return;
  const to = canvasPoint(event);
  Module.ccall(drag.pan ? 'kappa_pan' : 'kappa_orbit', null, ['number', 'number', 'number', 'number'],
               [drag.at[0], drag.at[1], to[0], to[1]]);
  drag.at = to;
  requestDraw();
});
canvas.addEventListener('pointerup', () => {
  drag = null;
  rest(0);
});
canvas.addEventListener('wheel', event => {
  event.preventDefault();
  const [x, y] = canvasPoint(event);
  moving();
  Module.ccall('kappa_zoom', null, ['number', 'number', 'number'], [event.deltaY < 0 ? 1 : -1, x, y]);
  requestDraw();
  rest(250);
}, { passive: false });

// --- the panel: the settings table -------------------------------------------------

// Where each setting goes in the panel, as in the desktop viewer's (app/viewer/ui_panel.cpp);
// settings not named here are listed under "More".
const panelSections = [
  ['Lines', ['hidden-lines', 'fade', 'detail', 'line-width', 'line-color']],
  ['Surface', ['shading', 'light', 'light-frame', 'colormap', 'colorbar', 'hatching', 'hatch-spacing',
               'hatch-style', 'background', 'msaa']],
];

function setSetting(name, value) {
  try {
    call('kappa_set', name, String(value));
    requestDraw();
  } catch (e) {
    fail(e.message);
  }
  refreshPanel();
}

function element(tag, attributes, ...children) {
  const e = document.createElement(tag);
  Object.assign(e, attributes || {});
  for (const c of children) e.append(c);
  return e;
}

function labelled(setting, ...controls) {
  const label = element('label', { title: '--' + setting.name + ': ' + setting.help },
                        element('span', { className: 'name', textContent: setting.label }), ...controls);
  return label;
}

function sliderWidget(s) {
  const log = s.log && s.min > 0;
  const toSlider = v => (log ? Math.log(v) : v);
  const fromSlider = v => (log ? Math.exp(v) : v);
  const slider = element('input', { type: 'range', min: toSlider(s.min), max: toSlider(s.max),
                                    step: s.kind === 'integer' ? 1 : (toSlider(s.max) - toSlider(s.min)) / 200,
                                    value: toSlider(s.value) });
  const shown = element('output', { textContent: Number(s.value).toPrecision(3).replace(/\.?0+$/, '') });
  const value = () => (s.kind === 'integer' ? Math.round(fromSlider(+slider.value))
                                             : +fromSlider(+slider.value).toPrecision(4));
  slider.addEventListener('input', () => { shown.textContent = value(); });
  // Settings that prepare the mesh again (the detail) change on release, the rest as they move.
  slider.addEventListener(s.name === 'detail' ? 'change' : 'input', () => setSetting(s.name, value()));
  if (!s.can_be_off) return labelled(s, slider, shown);
  const on = element('input', { type: 'checkbox', checked: s.value > 0 });
  on.addEventListener('change', () => setSetting(s.name, on.checked ? fromSlider((+slider.min + +slider.max) / 2) : 'off'));
  slider.disabled = !(s.value > 0);
  return labelled(s, on, slider, shown);
}

function settingWidget(s) {
  if (s.kind === 'choice' && s.choices.length === 2 && s.choices[0] === 'off' && s.choices[1] === 'on') {
    const box = element('input', { type: 'checkbox', checked: s.value === 'on' });
    box.addEventListener('change', () => setSetting(s.name, box.checked ? 'on' : 'off'));
    return labelled(s, box);
  }
  if (s.kind === 'choice') {
    const select = element('select', {}, ...s.choices.map(c => element('option', { value: c, textContent: c })));
    select.value = s.value;
    select.addEventListener('change', () => setSetting(s.name, select.value));
    return labelled(s, select);
  }
  if (s.kind === 'number' || s.kind === 'integer') return sliderWidget(s);
  if (s.kind === 'color') {
    const picker = element('input', { type: 'color', value: s.value });
    picker.addEventListener('input', () => setSetting(s.name, picker.value));
    return labelled(s, picker);
  }
  const text = element('input', { type: 'text', value: s.value, size: 12 });
  text.addEventListener('change', () => setSetting(s.name, text.value));
  return labelled(s, text);
}

function refreshPanel() {
  if (params.get('panel') === 'off') return;
  const table = JSON.parse(Module.ccall('kappa_settings', 'string', [], []));
  const byName = new Map(table.settings.map(s => [s.name, s]));
  const root = document.getElementById('settings');
  root.replaceChildren();
  // Line kinds: a checkbox each, then the thresholds of those that are on.
  root.append(element('h2', { textContent: 'Lines' }));
  const onKinds = () => table.lines.flatMap(g => g.lines).filter(l => l.on).map(l => l.kind);
  for (const group of table.lines) {
    root.append(element('h3', { textContent: group.title }));
    const sliders = [];
    for (const line of group.lines) {
      const box = element('input', { type: 'checkbox', checked: line.on });
      box.addEventListener('change', () => {
        line.on = box.checked;
        const kinds = onKinds();
        setSetting('lines', kinds.length ? kinds.join(',') : 'none');
      });
      root.append(element('label', { title: '--lines ' + line.kind }, box, line.label));
      if (line.on && line.setting && !sliders.includes(line.setting)) sliders.push(line.setting);
    }
    for (const name of sliders) if (byName.has(name)) root.append(settingWidget(byName.get(name)));
  }
  const placed = new Set(['lines', ...table.lines.flatMap(g => g.lines).map(l => l.setting)]);
  for (const [title, names] of panelSections) {
    if (title !== 'Lines') root.append(element('h2', { textContent: title }));
    for (const name of names) {
      placed.add(name);
      if (byName.has(name)) root.append(settingWidget(byName.get(name)));
    }
  }
  const more = table.settings.filter(s => !placed.has(s.name));
  if (more.length) {
    const details = element('details', {}, element('summary', { textContent: 'More' }));
    for (const s of more) details.append(settingWidget(s));
    root.append(element('h2', { textContent: 'Output' }), details);
  }
}

// --- downloads -------------------------------------------------------------------

function download(blob, name) {
  const a = element('a', { href: URL.createObjectURL(blob), download: name });
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}

// The SVG of the current view, by the command line's writer (render/vector/svg_writer.cpp).
function svgText() {
  call('kappa_write', '/output/view.svg');
  const text = Module.FS.readFile('/output/view.svg', { encoding: 'utf8' });
  Module.FS.unlink('/output/view.svg');
  requestDraw();  // the canvas is drawn again after the vector pass used the renderer
  return text;
}

// The view drawn with its own fields (prepared now if the slices have not finished).
function drawComplete() {
  if (Module.ccall('kappa_prepare', 'number', ['number'], [1e9]) === 1)
    throw new Error(Module.ccall('kappa_message', 'string', [], []));
  call('kappa_draw');
}

function pngDataUrl() {
  drawComplete();
  return canvas.toDataURL('image/png');
}

document.getElementById('save-png').addEventListener('click', () => {
  try {
    drawComplete();
    canvas.toBlob(blob => download(blob, meshName + '.png'), 'image/png');
  } catch (e) {
    fail(e.message);
  }
});
document.getElementById('save-svg').addEventListener('click', () => {
  try {
    download(new Blob([svgText()], { type: 'image/svg+xml' }), meshName + '.svg');
  } catch (e) {
    fail(e.message);
  }
});
document.getElementById('reset').addEventListener('click', () => {
  try {
    call('kappa_view', params.get('view') || '');
    requestDraw();
  } catch (e) {
    fail(e.message);
  }
});
document.getElementById('file').addEventListener('change', event => openFiles(event.target.files));
for (const type of ['dragenter', 'dragover']) {
  window.addEventListener(type, event => {
    event.preventDefault();
    document.body.classList.add('dragging');
  });
}
window.addEventListener('dragleave', event => {
  if (!event.relatedTarget) document.body.classList.remove('dragging');
});
window.addEventListener('drop', event => {
  event.preventDefault();
  document.body.classList.remove('dragging');
  openFiles(event.dataTransfer.files);
});

// For scripts and tests (tests/web/): what the buttons do, as values.
window.kappaPage = { openUrl, openBytes, openFiles, svgText, pngDataUrl, setSetting, times,
                     preparing: () => preparation !== null || drawPending };

// --- start -------------------------------------------------------------------------

function start() {
  Module.FS.mkdir('/input');
  Module.FS.mkdir('/output');
  Module.FS.chdir('/input');  // file names in messages as the command line shows them
  call('kappa_start', '#canvas');
  if (params.get('panel') === 'off') {
    document.body.classList.add('bare');
    document.getElementById('panel').style.display = 'none';
  }
  const size = params.get('size');
  if (size !== null) {
    const m = /^(\d+)x(\d+)$/.exec(size);
    if (!m) throw new Error("--size expects WxH, got '" + size + "'");
    fixedSize = [+m[1], +m[2]];
  }
  window.addEventListener('resize', layout);
  layout();
  if (params.has('view')) call('kappa_view', params.get('view'));
  // Any appearance setting by its command-line name (lines=LIST, shading=NAME, colormap=NAME,
  // colorbar=on, ...), checked by the settings table's own parser as `kappa render` checks it.
  const settings = JSON.parse(Module.ccall('kappa_settings', 'string', [], [])).settings;
  const names = new Set(['lines', ...settings.map(s => s.name)]);
  for (const [name, value] of params) if (names.has(name)) call('kappa_set', name, value);
  refreshPanel();
  if (params.has('mesh')) return openUrl(params.get('mesh'));
  // No mesh: the built-in model, as `kappa view` without MESH.
  call('kappa_open', '');
  showMessage('The built-in model. Open a mesh with the file picker above, drop a file here, or ?mesh=URL.', false);
  readyWhenDrawn = true;
  requestDraw();
  refreshPanel();
}

var Module = {
  canvas,
  print: text => console.log(text),
  printErr: text => console.warn(text),
  onRuntimeInitialized: () => {
    try {
      start();
    } catch (e) {
      fail(e.message);
    }
  },
};
