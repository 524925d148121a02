// index.html of a run (testbed/report/report_html.h): renders the page's sections from the
// JSON in the page-data script element. Embedded into every page at build time; no library, no
// network. Images the inspector reads are data: URIs, which keep a canvas readable under
// file:// (an image from another file would taint it).
'use strict';
(function () {
  const page = JSON.parse(document.getElementById('page-data').textContent);

  function el(tag, attributes, ...children) {
    const node = document.createElement(tag);
    for (const [key, value] of Object.entries(attributes || {})) {
      if (key === 'text') node.textContent = value;
      else if (key === 'class') node.className = value;
      else node.setAttribute(key, value);
    }
    for (const child of children) if (child) node.appendChild(child);
    return node;
  }

  function heading(section) {
    return section.title ? el('h2', { text: section.title }) : null;
  }

  function notes(section) {
    const box = document.createDocumentFragment();
    for (const line of section.notes || []) box.appendChild(el('p', { class: 'note', text: line }));
    return box;
  }

  // Entries coloured by value, one scale for the whole table (lower is better: green to red),
  // logarithmic where the values span more than two decades: errors across scenes do.
  function colourByValue(rows, section) {
    const values = [];
    for (const r of rows) r.cells.forEach((c, i) => { if (section.columns[i].numeric && Number.isFinite(c.v)) values.push(c.v); });
    if (values.length < 2) return;
    const low = Math.min(...values);
    const high = Math.max(...values);
    const logarithmic = low > 0 && high / low > 100;
    const position = (v) => (logarithmic ? Math.log(v / low) / Math.log(high / low) : (v - low) / (high - low || 1));
    for (const r of rows) {
      r.cells.forEach((c, i) => {
        if (!section.columns[i].numeric || !Number.isFinite(c.v)) return;
        r.tr.children[i].style.background = 'hsl(' + Math.round(120 * (1 - position(c.v))) + ', 65%, 82%)';
      });
    }
  }

  // Rows shown only where every word typed is in their text.
  function filterBox(rows) {
    const input = el('input', { type: 'search', class: 'filter', placeholder: 'filter rows: words that must all appear' });
    for (const r of rows) r.text = r.cells.map((c) => c.t).join(' ').toLowerCase();
    input.addEventListener('input', () => {
      const words = input.value.toLowerCase().split(/\s+/).filter(Boolean);
      for (const r of rows) r.tr.hidden = !words.every((w) => r.text.includes(w));
    });
    return input;
  }

  // A table whose columns sort on a click: numbers by value (missing ones last), text as text.
  // `heat` colours its entries by value, `filter` adds a row filter, `collapsed` folds it away
  // (a link to one of its rows unfolds it: revealTarget).
  function table(section) {
    const head = el('tr');
    const body = el('tbody');
    const rows = section.rows.map((row) => {
      const tr = el('tr', row.id ? { id: row.id } : {});
      row.cells.forEach((cell, i) => {
        const td = el('td', section.columns[i].numeric ? { class: 'num' } : {});
        td.appendChild(cell.href ? el('a', { href: cell.href, text: cell.t }) : document.createTextNode(cell.t));
        tr.appendChild(td);
      });
      body.appendChild(tr);
      return { tr, cells: row.cells };
    });
    let sortedBy = -1;
    let direction = 1;
    section.columns.forEach((column, i) => {
      const th = el('th', { text: column.heading, title: 'sort' });
      th.addEventListener('click', () => {
        direction = sortedBy === i ? -direction : 1;
        sortedBy = i;
        const key = (r) => r.cells[i].v;
        rows.sort((a, b) => {
          if (column.numeric) {
            const x = key(a);
            const y = key(b);
            if (x === null || x === undefined) return 1;
            if (y === null || y === undefined) return -1;
            return direction * (x - y);
          }
          return direction * a.cells[i].t.localeCompare(b.cells[i].t);
        });
        for (const r of rows) body.appendChild(r.tr);
        for (const other of head.children) other.classList.remove('sorted-up', 'sorted-down');
        th.classList.add(direction > 0 ? 'sorted-up' : 'sorted-down');
      });
      head.appendChild(th);
    });
    if (section.heat) colourByValue(rows, section);
    const content = el('div', {}, section.filter ? filterBox(rows) : null,
                       el('div', { class: 'scroll' }, el('table', { class: 'records' }, el('thead', {}, head), body)));
    const box = el('section', {}, heading(section), notes(section));
    if (!section.collapsed) box.appendChild(content);
    else box.appendChild(el('details', { class: 'folded' }, el('summary', { text: rows.length + ' rows (click to fold or unfold)' }), content));
    return box;
  }

  // The row a #link names, made visible: its folded table unfolded, a filter hiding it cleared.
  function revealTarget() {
    const id = decodeURIComponent(location.hash.slice(1));
    const target = id && document.getElementById(id);
    if (!target) return;
    const folded = target.closest('details');
    if (folded) folded.open = true;
    if (target.hidden) {
      const filter = target.closest('section').querySelector('input.filter');
      filter.value = '';
      filter.dispatchEvent(new Event('input'));
    }
    target.scrollIntoView({ block: 'center' });
  }

  function figure(section) {
    const box = el('figure');
    if (section.svg) {
      const holder = el('div');
      holder.innerHTML = section.svg;  // written by the testbed itself (report_plot.cpp)
      box.appendChild(holder);
    } else {
      const image = el('img', { src: section.src, alt: section.title || section.src, loading: 'lazy' });
      image.addEventListener('error', () => box.classList.add('missing'));
      box.appendChild(section.href ? el('a', { href: section.href }, image) : image);
    }
    const wrapper = el('section', {}, heading(section), notes(section), box);
    return wrapper;
  }

  function videos(section) {
    const box = el('div', { class: 'videos' });
    for (const item of section.items) {
      const f = el('figure', {}, el('figcaption', { text: item.title }));
      if (item.video) f.appendChild(el('video', { src: item.video, controls: '', muted: '', loop: '', preload: 'metadata' }));
      if (item.plot) f.appendChild(el('img', { src: item.plot, alt: item.title + ': error over time', loading: 'lazy' }));
      box.appendChild(f);
    }
    return el('section', {}, heading(section), notes(section), box);
  }

  function links(section) {
    const list = el('ul', { class: 'links' });
    for (const item of section.items) list.appendChild(el('li', {}, el('a', { href: item.href, text: item.text })));
    return el('section', {}, heading(section), notes(section), list);
  }

  function loadImage(uri) {
    const image = new Image();
    image.src = uri;
    return image.decode().then(() => image);
  }

  // The pixels of a decoded data: image, for the inspector.
  function pixelsOf(image) {
    const canvas = document.createElement('canvas');
    canvas.width = image.naturalWidth;
    canvas.height = image.naturalHeight;
    const context = canvas.getContext('2d', { willReadFrequently: true });
    context.drawImage(image, 0, 0);
    return context.getImageData(0, 0, canvas.width, canvas.height).data;
  }

  // Technique | reference (flip, split slider) beside the error map, one zoom and pan for
  // both panes, nearest-neighbour pixels up to 32x, a pixel inspector and close-ups of the
  // same windows for every technique.
  function viewer(section) {
    const W = section.width;
    const H = section.height;
    const maxZoom = 32;
    const state = { t: 0, flipped: false, split: 1, zoom: 0, cx: W / 2, cy: H / 2 };
    const root = el('section', { class: 'viewer', tabindex: '0' }, heading(section), notes(section));
    const select = el('select', { 'aria-label': 'technique' });
    section.techniques.forEach((t, i) => select.appendChild(el('option', { value: String(i), text: t.id })));
    const flip = el('button', { type: 'button', text: 'flip (F)' });
    const slider = el('input', { type: 'range', min: '0', max: '100', value: '100', 'aria-label': 'split' });
    const zoomText = el('span');
    root.appendChild(el('div', { class: 'viewer-controls' }, el('label', { text: 'technique ' }, select), flip,
      el('label', { text: 'split technique | reference ' }, slider), zoomText));
    root.appendChild(el('div', { class: 'keys', text: 'Keys: F or space flips technique / reference, ← → (or J K) ' +
      'change technique, + − zoom, 0 fits, drag pans, wheel zooms; click a close-up to go there.' }));
    const paneA = el('canvas', { 'aria-label': 'technique or reference' });
    const paneB = el('canvas', { 'aria-label': 'error map' });
    const labelA = el('span', { class: 'label' });
    const labelB = el('span', { class: 'label', text: 'error map against the reference' });
    root.appendChild(el('div', { class: 'viewer-panes' }, el('div', { class: 'pane' }, paneA, labelA),
      el('div', { class: 'pane' }, paneB, labelB)));
    const inspector = el('div', { class: 'inspector', text: 'move the pointer over an image' });
    root.appendChild(inspector);
    const closeups = el('table', { class: 'closeups' });
    if (section.windows.length) {
      root.appendChild(el('h2', { text: 'Close-ups: the same windows for every technique' }));
      root.appendChild(el('p', { class: 'note', text: section.windowsNote || '' }));
      root.appendChild(el('div', { class: 'scroll' }, closeups));
    }

    let reference = null;
    const loaded = [];
    const pixels = new Map();
    function visPixels(entry) {
      if (!pixels.has(entry)) pixels.set(entry, pixelsOf(entry.vis));
      return pixels.get(entry);
    }

    function fitZoom() {
      return paneA.clientWidth / W;
    }
    function clampView() {
      state.zoom = Math.min(maxZoom, Math.max(fitZoom(), state.zoom || 0));
      state.cx = Math.min(W, Math.max(0, state.cx));
      state.cy = Math.min(H, Math.max(0, state.cy));
    }
    function setTransform(context, canvas) {
      const dpr = canvas.width / canvas.clientWidth;
      context.setTransform(state.zoom * dpr, 0, 0, state.zoom * dpr,
        (canvas.clientWidth / 2 - state.cx * state.zoom) * dpr, (canvas.clientHeight / 2 - state.cy * state.zoom) * dpr);
      context.imageSmoothingEnabled = false;
    }
    function sizeCanvas(canvas) {
      const dpr = window.devicePixelRatio || 1;
      const width = canvas.clientWidth;
      const height = Math.round(width * H / W);
      canvas.style.height = height + 'px';
      if (canvas.width !== Math.round(width * dpr) || canvas.height !== Math.round(height * dpr)) {
        canvas.width = Math.round(width * dpr);
        canvas.height = Math.round(height * dpr);
      }
    }
    function draw() {
      if (!reference) return;
      for (const canvas of [paneA, paneB]) sizeCanvas(canvas);
      clampView();
      const technique = loaded[state.t];
      const a = paneA.getContext('2d');
      a.setTransform(1, 0, 0, 1, 0, 0);
      a.clearRect(0, 0, paneA.width, paneA.height);
      setTransform(a, paneA);
      a.drawImage(state.flipped ? reference.vis : technique.vis, 0, 0);
      if (!state.flipped && state.split < 1) {
        const splitX = state.split * paneA.width;
        a.save();
        a.setTransform(1, 0, 0, 1, 0, 0);
        a.beginPath();
        a.rect(splitX, 0, paneA.width - splitX, paneA.height);
        a.clip();
        setTransform(a, paneA);
        a.drawImage(reference.vis, 0, 0);
        a.restore();
        a.setTransform(1, 0, 0, 1, 0, 0);
        a.fillStyle = '#ffd21a';
        a.fillRect(splitX - 1, 0, 2, paneA.height);
      }
      const b = paneB.getContext('2d');
      b.setTransform(1, 0, 0, 1, 0, 0);
      b.clearRect(0, 0, paneB.width, paneB.height);
      setTransform(b, paneB);
      b.drawImage(technique.error, 0, 0);
      const showing = state.flipped ? section.reference.label : section.techniques[state.t].id;
      root.dataset.showing = state.flipped ? 'reference' : section.techniques[state.t].id;
      labelA.textContent = state.flipped || state.split >= 1 ? showing
        : section.techniques[state.t].id + ' | ' + section.reference.label;
      labelB.textContent = 'error map: ' + section.techniques[state.t].id + ' against ' + section.reference.label;
      zoomText.textContent = 'zoom ' + state.zoom.toFixed(2) + '×';
      select.value = String(state.t);
    }

    function imagePoint(canvas, event) {
      const box = canvas.getBoundingClientRect();
      return { x: state.cx + (event.clientX - box.left - canvas.clientWidth / 2) / state.zoom,
               y: state.cy + (event.clientY - box.top - canvas.clientHeight / 2) / state.zoom };
    }
    function zoomAround(canvas, event, factor) {
      const before = imagePoint(canvas, event);
      state.zoom = Math.min(maxZoom, Math.max(fitZoom(), state.zoom * factor));
      const after = imagePoint(canvas, event);
      state.cx += before.x - after.x;
      state.cy += before.y - after.y;
      draw();
    }
    function valueText(entry, x, y) {
      const data = visPixels(entry);
      const i = 4 * (y * W + x);
      return data[i + 3] === 0 ? 'background' : (data[i] / 255).toFixed(3);
    }
    function inspect(canvas, event) {
      if (!reference) return;
      const p = imagePoint(canvas, event);
      const x = Math.floor(p.x);
      const y = Math.floor(p.y);
      if (x < 0 || y < 0 || x >= W || y >= H) {
        inspector.textContent = 'outside the image';
        return;
      }
      const id = section.techniques[state.t].id;
      inspector.textContent = 'pixel (' + x + ', ' + y + ')  visibility: ' + id + ' ' + valueText(loaded[state.t], x, y) +
        ' · ' + section.reference.label + ' ' + valueText(reference, x, y) + '  (8-bit, as the PNGs)';
    }
    for (const canvas of [paneA, paneB]) {
      let drag = null;
      canvas.addEventListener('wheel', (event) => {
        event.preventDefault();
        zoomAround(canvas, event, Math.pow(2, -event.deltaY / 240));
      }, { passive: false });
      canvas.addEventListener('pointerdown', (event) => {
        drag = { x: event.clientX, y: event.clientY };
        canvas.setPointerCapture(event.pointerId);
        root.focus();
      });
      canvas.addEventListener('pointerup', () => { drag = null; });
      canvas.addEventListener('pointermove', (event) => {
        if (drag) {
          state.cx -= (event.clientX - drag.x) / state.zoom;
          state.cy -= (event.clientY - drag.y) / state.zoom;
          drag = { x: event.clientX, y: event.clientY };
          draw();
        }
        inspect(canvas, event);
      });
    }
    function step(delta) {
      const n = section.techniques.length;
      state.t = (state.t + delta + n) % n;
      draw();
    }
    document.addEventListener('keydown', (event) => {
      if (event.target.tagName === 'INPUT' || event.target.tagName === 'SELECT') return;
      const actions = {
        f: () => { state.flipped = !state.flipped; draw(); },
        ' ': () => { state.flipped = !state.flipped; draw(); },
        ArrowRight: () => step(1), k: () => step(1), ArrowLeft: () => step(-1), j: () => step(-1),
        '+': () => { state.zoom *= 2; draw(); }, '=': () => { state.zoom *= 2; draw(); },
        '-': () => { state.zoom /= 2; draw(); }, '0': () => { state.zoom = 0; state.cx = W / 2; state.cy = H / 2; draw(); },
      };
      const action = actions[event.key] || actions[event.key.toLowerCase()];
      if (!action) return;
      event.preventDefault();
      action();
    });
    flip.addEventListener('click', () => { state.flipped = !state.flipped; draw(); });
    select.addEventListener('change', () => { state.t = Number(select.value); draw(); });
    slider.addEventListener('input', () => { state.split = Number(slider.value) / 100; draw(); });
    window.addEventListener('resize', draw);

    function goTo(windowBox, techniqueIndex) {
      if (techniqueIndex !== null) state.t = techniqueIndex;
      state.flipped = techniqueIndex === null;
      state.zoom = paneA.clientWidth / windowBox.size;
      state.cx = windowBox.x + windowBox.size / 2;
      state.cy = windowBox.y + windowBox.size / 2;
      draw();
      root.scrollIntoView({ block: 'start' });
    }
    function buildCloseups() {
      const header = el('tr', {}, el('th'));
      section.windows.forEach((w, k) => header.appendChild(el('th', { text: 'window ' + (k + 1) + ' (' + w.x + ', ' + w.y + ')' })));
      closeups.appendChild(header);
      const rows = [{ label: section.reference.label, entry: reference, index: null }]
        .concat(section.techniques.map((t, i) => ({ label: t.id, entry: loaded[i], index: i })));
      for (const row of rows) {
        const tr = el('tr', {}, el('th', { text: row.label }));
        for (const w of section.windows) {
          const canvas = el('canvas', { width: String(w.size), height: String(w.size), title: row.label });
          const context = canvas.getContext('2d');
          context.imageSmoothingEnabled = false;
          context.drawImage(row.entry.vis, w.x, w.y, w.size, w.size, 0, 0, w.size, w.size);
          canvas.addEventListener('click', () => goTo(w, row.index));
          tr.appendChild(el('td', {}, canvas));
        }
        closeups.appendChild(tr);
      }
    }

    const entries = [section.reference].concat(section.techniques);
    Promise.all(entries.map((entry) => Promise.all([loadImage(entry.vis), entry.error ? loadImage(entry.error) : null])))
      .then((images) => {
        reference = { vis: images[0][0] };
        images.slice(1).forEach(([vis, error]) => loaded.push({ vis, error }));
        buildCloseups();
        draw();
        root.dataset.ready = 'true';
      })
      .catch((error) => console.error('viewer: ' + error));
    return root;
  }

  // compare --frames' frame viewer: the kept frames of every entry on sheets (one image per
  // entry and kind, frames in a grid), one frame at a time on a canvas; the chart below holds
  // every entry's per-frame error on one scale, with the current frame marked.
  function frames(section) {
    const w = section.frame.width;
    const h = section.frame.height;
    const count = section.frames.length;
    const state = { entry: Math.min(1, section.entries.length - 1), index: 0, flipped: false, error: false, zoom: 1 };
    const root = el('section', { class: 'frame-viewer', tabindex: '0' }, heading(section), notes(section));
    const picker = el('select', { 'aria-label': 'technique' });
    section.entries.forEach((entry, i) => picker.appendChild(el('option', { value: String(i), text: entry.id })));
    picker.value = String(state.entry);
    const slider = el('input', { type: 'range', min: '0', max: String(count - 1), value: '0', 'aria-label': 'frame' });
    const label = el('span', { class: 'inspector' });
    const canvas = el('canvas', { width: String(w), height: String(h) });
    const chart = el('canvas', { class: 'frame-chart', width: '960', height: '180' });
    root.appendChild(el('div', { class: 'viewer-controls' }, picker, slider, label));
    root.appendChild(el('div', { class: 'frame-pane' }, canvas));
    root.appendChild(chart);
    const sheets = section.entries.map((entry) => {
      const load = (src) => { const image = new Image(); image.src = src; return image; };
      return { shaded: load(entry.shaded), error: load(entry.error) };
    });

    function draw() {
      const shown = state.flipped ? 0 : state.entry;
      const sheet = sheets[shown][state.error ? 'error' : 'shaded'];
      const x = (state.index % section.columns) * w;
      const y = Math.floor(state.index / section.columns) * h;
      const context = canvas.getContext('2d');
      context.imageSmoothingEnabled = false;
      context.fillStyle = '#26323f';
      context.fillRect(0, 0, w, h);
      const side = 1 / state.zoom;  // the shown part of the frame, centred
      if (sheet.complete && sheet.naturalWidth) {
        context.drawImage(sheet, x + (w - w * side) / 2, y + (h - h * side) / 2, w * side, h * side, 0, 0, w, h);
      }
      slider.value = String(state.index);
      const entry = section.entries[shown];
      const value = entry.series[state.index];
      label.textContent = 'frame ' + section.frames[state.index] + ' (' + (state.index + 1) + '/' + count + ') · ' +
        entry.id + (state.error ? ' error map' : '') + ' · ' + section.metric + ' ' +
        (value === null || value === undefined ? '–' : value.toPrecision(3)) + (state.zoom > 1 ? ' · zoom ' + state.zoom + '×' : '');
      root.dataset.showing = entry.id + (state.error ? ':error' : '') + '@' + state.index;
      drawChart();
    }

    function drawChart() {
      const context = chart.getContext('2d');
      const W = chart.width;
      const H = chart.height;
      const left = 48;
      context.clearRect(0, 0, W, H);
      let high = 0;
      for (const entry of section.entries) for (const v of entry.series) if (Number.isFinite(v)) high = Math.max(high, v);
      high = high || 1;
      const px = (i) => left + (count > 1 ? (i / (count - 1)) * (W - left - 8) : 0);
      const py = (v) => H - 16 - (v / high) * (H - 28);
      context.strokeStyle = '#999';
      context.beginPath(); context.moveTo(left, 8); context.lineTo(left, H - 16); context.lineTo(W - 8, H - 16); context.stroke();
      context.fillStyle = '#555';
      context.font = '11px sans-serif';
      context.fillText(high.toPrecision(3), 2, 14);
      context.fillText('0', 2, H - 16);
      context.fillText(section.metric + ' per frame', left + 6, 14);
      section.entries.forEach((entry, e) => {
        context.strokeStyle = 'hsl(' + Math.round((360 * e) / section.entries.length) + ', 70%, 42%)';
        context.lineWidth = e === state.entry ? 2.5 : 1;
        context.beginPath();
        entry.series.forEach((v, i) => { if (Number.isFinite(v)) context[i ? 'lineTo' : 'moveTo'](px(i), py(v)); });
        context.stroke();
      });
      context.strokeStyle = '#000';
      context.lineWidth = 1;
      context.beginPath(); context.moveTo(px(state.index), 8); context.lineTo(px(state.index), H - 16); context.stroke();
    }

    function go(index) {
      state.index = Math.max(0, Math.min(count - 1, index));
      draw();
    }
    picker.addEventListener('change', () => { state.entry = Number(picker.value); state.flipped = false; draw(); });
    slider.addEventListener('input', () => go(Number(slider.value)));
    chart.addEventListener('click', (event) => {
      const box = chart.getBoundingClientRect();
      const x = ((event.clientX - box.left) / box.width) * chart.width;
      go(Math.round(((x - 48) / (chart.width - 56)) * (count - 1)));
    });
    root.addEventListener('keydown', (event) => {
      const keys = {
        ArrowRight: () => go(state.index + 1), ArrowLeft: () => go(state.index - 1),
        Home: () => go(0), End: () => go(count - 1),
        f: () => { state.flipped = !state.flipped; draw(); }, e: () => { state.error = !state.error; draw(); },
        '+': () => { state.zoom = Math.min(16, state.zoom * 2); draw(); },
        '-': () => { state.zoom = Math.max(1, state.zoom / 2); draw(); },
      };
      if (keys[event.key]) { keys[event.key](); event.preventDefault(); }
    });
    for (const sheet of sheets) for (const image of [sheet.shaded, sheet.error]) image.addEventListener('load', draw);
    draw();
    return root;
  }

  const renderers = { table, figure, videos, links, viewer, frames };
  const main = document.getElementById('main');
  main.appendChild(el('h1', { text: page.title }));
  for (const line of page.notes || []) main.appendChild(el('p', { class: 'note', text: line }));
  for (const section of page.sections) main.appendChild(renderers[section.type](section));
  window.addEventListener('hashchange', revealTarget);
  revealTarget();
})();
