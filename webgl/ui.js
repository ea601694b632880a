// The HTML controls: buttons, inputs, readouts, legend, notes, errors, help and
// keyboard shortcuts. Holds no simulation state: it calls the app's handlers and
// shows what the app tells it.
'use strict';

window.clothUI = (function () {
  const PRESET_KEYS = { '1': 'curtain', '2': 'corners', '3': 'chain', '4': 'large' };

  function $(id) { return document.getElementById(id); }

  // Mark the checked option of a segmented radio group (no reliance on CSS :has()).
  function checkRadio(name, value) {
    document.querySelectorAll('input[name=' + name + ']').forEach(function (r) {
      r.checked = r.value === value;
      r.parentElement.classList.toggle('on', r.checked);
    });
  }

  function fmt(v, digits) {
    if (!Number.isFinite(v)) return '–';
    if (v !== 0 && (Math.abs(v) < 0.001 || Math.abs(v) >= 1e4)) return v.toExponential(2);
    return v.toFixed(digits);
  }

  // h: {pause, step, reset, preset(name), solver(name), param(key, raw), mode(m), scaleMode(m),
  //     fullScale(raw), loadJson(text), currentJson() -> text}
  function create(h) {
    const el = {
      pause: $('btn-pause'), step: $('btn-step'), reset: $('btn-reset'), help: $('btn-help'),
      preset: $('preset'), fullScale: $('full-scale'), note: $('note'),
      banner: $('banner'), bannerText: $('banner-text'), bannerClose: $('banner-close'),
      fatal: $('fatal'), helpBox: $('help'), helpClose: $('help-close'),
      json: $('scene-json'), jsonBox: $('json-box'), loadJson: $('btn-load-json'), showJson: $('btn-show-json'),
      paused: $('r-paused'), legend: $('legend'), legendTitle: $('legend-title'),
      legendLo: $('legend-lo'), legendMid: $('legend-mid'), legendHi: $('legend-hi'),
      sim: $('r-sim'), render: $('r-render'), fps: $('r-fps'), rms: $('r-rms'), max: $('r-max'), size: $('r-size'),
    };
    const params = ['cols', 'rows', 'iterations', 'substeps', 'gravity', 'damping'];
    let noteTimer = 0;

    el.pause.addEventListener('click', function () { h.pause(); });
    el.step.addEventListener('click', function () { h.step(); });
    el.reset.addEventListener('click', function () { h.reset(); });
    el.help.addEventListener('click', function () { ui.showHelp(true); });
    el.helpClose.addEventListener('click', function () { ui.showHelp(false); });
    el.helpBox.addEventListener('click', function (e) { if (e.target === el.helpBox) ui.showHelp(false); });
    el.bannerClose.addEventListener('click', function () { ui.clearError(); });
    el.preset.addEventListener('change', function () { h.preset(el.preset.value); });
    $('solver').addEventListener('change', function () { h.solver($('solver').value); });
    params.forEach(function (key) {
      $(key).addEventListener('change', function () { h.param(key, $(key).value); });
    });
    document.querySelectorAll('input[name=mode]').forEach(function (r) {
      r.addEventListener('change', function () { if (r.checked) h.mode(r.value); });
    });
    document.querySelectorAll('input[name=scale]').forEach(function (r) {
      r.addEventListener('change', function () { if (r.checked) h.scaleMode(r.value); });
    });
    el.fullScale.addEventListener('change', function () { h.fullScale(el.fullScale.value); });
    el.loadJson.addEventListener('click', function () {
      try { h.loadJson(el.json.value); } catch (e) { /* shown in the banner */ }
    });
    el.showJson.addEventListener('click', function () { el.json.value = h.currentJson(); });

    window.addEventListener('keydown', function (e) {
      if (e.key === 'Escape') { ui.showHelp(false); return; }
      const t = e.target;
      if (e.ctrlKey || e.metaKey || e.altKey) return;
      if (t && (t.tagName === 'INPUT' || t.tagName === 'TEXTAREA' || t.tagName === 'SELECT')) return;
      const k = e.key;
      let handled = true;
      if (k === ' ') h.pause();
      else if (k === 's' || k === 'S' || k === 'ArrowRight') h.step();
      else if (k === 'r' || k === 'R') h.reset();
      else if (k === 'c' || k === 'C') h.mode(null);
      else if (k === 'a' || k === 'A') h.scaleMode(null);
      else if (k === 'h' || k === 'H' || k === '?') ui.showHelp(el.helpBox.hidden);
      else if (PRESET_KEYS[k]) h.preset(PRESET_KEYS[k]);
      else handled = false;
      if (handled) e.preventDefault();
    });

    const ui = {
      setParams: function (p) {
        params.forEach(function (key) { if (p[key] !== undefined) $(key).value = String(p[key]); });
      },
      setPreset: function (name) { el.preset.value = name; },
      setSolver: function (name) { $('solver').value = name; },
      setPaused: function (paused) {
        el.pause.textContent = paused ? 'Resume' : 'Pause';
        el.paused.hidden = !paused;
      },
      setMode: function (mode) {
        checkRadio('mode', mode);
        el.legend.classList.toggle('stress', mode === 'stress');
        el.legendTitle.textContent = mode === 'stress' ? 'stress Q / scale' : 'strain |diff|';
      },
      setScale: function (scaleMode, fullScale) {
        checkRadio('scale', scaleMode);
        el.fullScale.value = String(fullScale);
        el.fullScale.disabled = scaleMode !== 'fixed';
      },
      setLegend: function (scale, auto) {
        el.legendLo.textContent = '0';
        el.legendMid.textContent = fmt(scale / 2, 4);
        el.legendHi.textContent = fmt(scale, 4) + (auto ? ' (max)' : '');
      },
      setReadouts: function (r) {
        el.sim.textContent = fmt(r.simMs, 2);
        el.render.textContent = fmt(r.renderMs, 2);
        el.fps.textContent = fmt(r.fps, 0);
        el.rms.textContent = fmt(r.rms, 4);
        el.max.textContent = fmt(r.max, 4);
        el.size.textContent = r.size;
      },
      // A short-lived note under the inputs (clamped values).
      note: function (msg) {
        el.note.textContent = msg;
        el.note.hidden = !msg;
        clearTimeout(noteTimer);
        if (msg) noteTimer = setTimeout(function () { el.note.hidden = true; }, 6000);
      },
      error: function (msg) { el.bannerText.textContent = msg; el.banner.hidden = false; },
      clearError: function () { el.banner.hidden = true; el.bannerText.textContent = ''; },
      errorText: function () { return el.banner.hidden ? '' : el.bannerText.textContent; },
      noteText: function () { return el.note.hidden ? '' : el.note.textContent; },
      fatal: function (msg) { el.fatal.textContent = msg; el.fatal.hidden = !msg; },
      showHelp: function (show) { el.helpBox.hidden = !show; if (show) el.helpClose.focus(); },
    };
    return ui;
  }

  return { create: create, fmt: fmt };
})();
