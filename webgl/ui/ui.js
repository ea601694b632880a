// The HTML controls: buttons, inputs, readouts, legend, notes, errors, help and
// keyboard shortcuts. Holds no simulation state: it calls the app's handlers and
// shows what the app tells it.
import { clothCore } from '../sim/core.js';
import { clothFields } from './fields.js';
import { clothScenes } from '../sim/scenes.js';

export const clothUI = (function () {
  // Keys 1, 2, ... pick the presets in their order (sim/scenes.js PRESETS).
  const PRESET_KEYS = {};
  Object.keys(clothScenes.PRESETS).forEach(function (name, i) { PRESET_KEYS[String(i + 1)] = name; });
  const ACTION_KEYS = { p: 'replay', e: 'exportFile', l: 'copyLink' };

  function $(id) { return document.getElementById(id); }

  // Mark the checked option of a segmented radio group (no reliance on CSS :has()).
  function checkRadio(name, value) {
    document.querySelectorAll('input[name=' + name + ']').forEach(function (r) {
      r.checked = r.value === value;
      r.parentElement.classList.toggle('on', r.checked);
    });
  }

  const TEXT_INPUTS = { text: 1, number: 1, search: 1, email: 1, url: 1, tel: 1, password: 1 };
  const LEGEND_TOP = { max: '(top: max)', high: '(top: 99%)', floor: '(top: floor)', fixed: '(top: fixed)' };
  const ARROWS = { ArrowLeft: 1, ArrowRight: 1, ArrowUp: 1, ArrowDown: 1 };
  const BOX_SHOWN = 1 << 20;     // characters the Scene JSON box shows at most (see the box below)

  // Does the focused element use this key itself (see the keydown handler)?
  function ownsKey(t, k) {
    if (!t || !t.tagName) return false;
    const tag = t.tagName;
    if (tag === 'TEXTAREA' || t.isContentEditable) return true;
    if (tag === 'INPUT' && Object.prototype.hasOwnProperty.call(TEXT_INPUTS, t.type)) return true;
    if ((tag === 'BUTTON' || tag === 'SUMMARY' || tag === 'A') && (k === ' ' || k === 'Enter')) return true;
    if ((tag === 'SELECT' || (tag === 'INPUT' && t.type === 'radio')) && ARROWS[k]) return true;
    if (tag === 'SELECT' && (k === ' ' || k === 'Enter')) return true;
    return false;
  }

  // Hide an element. Hiding a focused element does not move focus at once (the browser fixes
  // it up at its next rendering update), so a key pressed right after would still go to the
  // hidden control (a Close button owns Space): blur what has focus inside it first.
  function hide(box) {
    const f = document.activeElement;
    if (f && f !== document.body && box.contains(f) && f.blur) f.blur();
    box.hidden = true;
  }

  function fmt(v, digits) {
    if (!Number.isFinite(v)) return '–';
    if (v !== 0 && (Math.abs(v) < 0.001 || Math.abs(v) >= 1e4)) return v.toExponential(2);
    return v.toFixed(digits);
  }

  // h: {pause, step, reset, preset(name), solver(name), material(name), param(key, raw), mode(m),
  //     scaleMode(m), fullScale(raw), loadJson(text), currentJson() -> text, replay, exportFile, copyLink,
  //     picture, video,
  //     openFile(file), charts(on), cutTool(on)}
  function create(h) {
    const el = {
      pause: $('btn-pause'), step: $('btn-step'), reset: $('btn-reset'), help: $('btn-help'),
      preset: $('preset'), fullScale: $('full-scale'), note: $('note'),
      banner: $('banner'), bannerText: $('banner-text'), bannerClose: $('banner-close'),
      fatal: $('fatal'), helpBox: $('help'), helpClose: $('help-close'),
      json: $('scene-json'), jsonBox: $('json-box'), loadJson: $('btn-load-json'), showJson: $('btn-show-json'),
      paused: $('r-paused'), legend: $('legend'), legendTitle: $('legend-title'), legendNote: $('legend-note'),
      legendLo: $('legend-lo'), legendMid: $('legend-mid'), legendHi: $('legend-hi'),
      sim: $('r-sim'), render: $('r-render'), fps: $('r-fps'), rms: $('r-rms'), max: $('r-max'), size: $('r-size'),
      recStatus: $('rec-status'), replay: $('r-replay'), replayFrame: $('r-replay-frame'), replayEnd: $('r-replay-end'),
      fileInput: $('file-input'),
    };
    // The Scene section's number fields, made from the core's list (cloth/scene.py
    // SCENE_FIELDS) before the Blade's box: captioned, ranged and read by fields.js.
    const LIMITS = clothScenes.LIMITS;
    const fieldKeys = clothScenes.SCENE_FIELDS;
    clothCore.schema().sceneFields.forEach(function (f) {
      const label = document.createElement('label'), input = document.createElement('input');
      input.id = f.key;
      if (LIMITS[f.key].off) input.placeholder = 'off';
      if (f.hint) label.title = f.hint.charAt(0).toUpperCase() + f.hint.slice(1);
      label.appendChild(document.createTextNode(' '));
      label.appendChild(input);
      $('scene-fields').insertBefore(label, $('blade-box'));
    });
    let noteTimer = 0;
    let errorAbout = '';   // what the shown error is about (error, clearError)
    let helpReturn = null;
    let helpOpen = false;   // the help is shown (modal)
    // A button clicked with a pointer gives focus back to the page, so that Space and the
    // other shortcuts work at once (a focused button would take Space and click itself
    // again: Reset twice). Keyboard clicks (detail 0) keep focus where the person put it.
    // Capture phase: before the button's own handler moves focus (the help's Close).
    document.addEventListener('click', function (e) {
      const b = e.target && e.target.closest ? e.target.closest('button') : null;
      if (b && e.detail > 0) b.blur();
    }, true);
    el.pause.addEventListener('click', function () { h.pause(); });
    el.step.addEventListener('click', function () { h.step(); });
    el.reset.addEventListener('click', function () { h.reset(); });
    el.help.addEventListener('click', function () { ui.showHelp(true); });
    el.helpClose.addEventListener('click', function () { ui.showHelp(false); });
    el.helpBox.addEventListener('click', function (e) { if (e.target === el.helpBox) ui.showHelp(false); });
    el.bannerClose.addEventListener('click', function () { ui.clearError(); });
    // The Preset and Solver menus, from the presets' and the core's lists. `custom` is what
    // the menu shows for a scene loaded as JSON; a person cannot pick it.
    function option(select, value, text, title) {
      const o = document.createElement('option');
      o.value = value;
      o.textContent = text;
      if (title) o.title = title;
      select.appendChild(o);
      return o;
    }
    const PRESETS = clothScenes.PRESETS;
    Object.keys(PRESETS).forEach(function (name) { option(el.preset, name, PRESETS[name].label); });
    option(el.preset, 'custom', 'Custom (JSON)').disabled = true;
    const SCHEMA = clothCore.schema(), SOLVERS = clothScenes.SOLVERS;
    SCHEMA.solvers.forEach(function (name) {
      const d = SOLVERS[name], chosen = name === SCHEMA.defaultSolver;
      option($('solver'), name, d.label,
             (chosen ? 'The default: ' : '') + d.substeps + ' step' + (d.substeps === 1 ? '' : 's') + ' a frame, ' +
             d.iterations + ' iteration' + (d.iterations === 1 ? '' : 's') + ' each (docs/physics.md)');
    });
    el.preset.addEventListener('change', function () { h.preset(el.preset.value); });
    // The help's numbers and names, from where they are declared.
    const names = Object.keys(PRESETS).map(function (n) { return PRESETS[n].label.toLowerCase(); });
    const facts = {
      defaultSubsteps: SOLVERS[SCHEMA.defaultSolver].substeps, seedIterations: SOLVERS[SCHEMA.seedSolver].iterations,
      presetFabric: clothScenes.MATERIALS[clothCore.fabrics().preset].label.toLowerCase(),
      handForce: SCHEMA.handForce, handRadius: 100 * SCHEMA.handRadius, presetCount: names.length, presetNames: names.join(', '), maxPanels: SCHEMA.maxPanels,
    };
    document.querySelectorAll('[data-fact]').forEach(function (node) { node.textContent = String(facts[node.dataset.fact]); });
    $('solver').addEventListener('change', function () { h.solver($('solver').value); });
    // The Material menu and its help rows, from the core's list of fabrics.
    const fabrics = clothScenes.MATERIALS;
    Object.keys(fabrics).forEach(function (name) {
      const m = fabrics[name];
      const o = document.createElement('option');
      o.value = name;
      o.textContent = m.label;
      o.title = m.stretch + ' N/m stretch, ' + m.shear + ' N/m shear, ' + m.density + ' kg/m², tears at ' + m.strength + ' N/m';
      $('material').appendChild(o);
      const row = document.createElement('tr');
      const what = document.createElement('td');
      const th = document.createElement('th');
      th.textContent = m.label;
      what.textContent = m.what + ': stretch ' + m.stretch + ' N/m, shear ' + m.shear + ' N/m, ' +
        m.density + ' kg/m², strength ' + m.strength + ' N/m';
      row.appendChild(th);
      row.appendChild(what);
      $('help-materials').appendChild(row);
    });
    const custom = document.createElement('option');
    custom.value = 'custom';
    custom.disabled = true;
    custom.textContent = 'Custom (scene)';
    $('material').appendChild(custom);
    $('material').addEventListener('change', function () { h.material($('material').value); });
    // The field a person has typed in and not yet committed (Enter, leaving it, an arrow key):
    // the settings shown again meanwhile (a script's or a replay's `set`) leave its text alone,
    // and leaving it uncommitted shows the setting as it is now.
    let typed = null, shown = null;
    fieldKeys.forEach(function (key) {
      const input = $(key);
      clothFields.attach(input, key, function (text) { typed = null; h.param(key, text); });
      input.addEventListener('input', function () { typed = input; });
      input.addEventListener('blur', function () {
        if (typed !== input) return;
        typed = null;
        if (shown) ui.setParams(shown);
      });
    });
    document.querySelectorAll('input[name=mode]').forEach(function (r) {
      r.addEventListener('change', function () { if (r.checked) h.mode(r.value); });
    });
    document.querySelectorAll('input[name=scale]').forEach(function (r) {
      r.addEventListener('change', function () { if (r.checked) h.scaleMode(r.value); });
    });
    clothFields.attach(el.fullScale, 'fullScale', function (text) { h.fullScale(text); });
    // The Scene JSON box never holds more than BOX_SHOWN characters: a textarea lays out all
    // of its text, and 17 MB pasted blocked the page for 8 s before Load could refuse it. A
    // longer text is held aside, unshown, and Load reads it; one past the scene limit is
    // refused as it is pasted or dropped, from its length (every character is a byte or more
    // in UTF-8), before anything reads it.
    const limit = clothCore.sceneLimit();
    const boxHint = el.json.placeholder;
    let heldText = null;
    function hold(text, what) {
      heldText = text;
      el.json.value = '';
      el.json.placeholder = what + ' ' + (text.length / 1e6).toFixed(1) + ' MB: too long to show here; Load reads it';
      ui.note(el.json.placeholder + '.');
    }
    function forget() { heldText = null; el.json.placeholder = boxHint; }
    function intoBox(e, data) {
      if (!data || Array.prototype.indexOf.call(data.types || [], 'Files') >= 0) return;  // a file: the page's drop
      const text = data.getData('text/plain') || data.getData('text') || '';
      if (text.length <= BOX_SHOWN) { forget(); return; }
      e.preventDefault();
      if (text.length > limit.bytes) { forget(); ui.error('Scene not pasted: ' + limit.message); return; }
      hold(text, e.type === 'drop' ? 'Dropped' : 'Pasted');
    }
    el.json.addEventListener('paste', function (e) { intoBox(e, e.clipboardData); });
    el.json.addEventListener('drop', function (e) { intoBox(e, e.dataTransfer); });
    // Typed, or set by a script or an input method: the same bounds, as the text comes in (20
    // MiB typed sat in the box, laid out, for 14 s before Load said it was too large).
    el.json.addEventListener('input', function () {
      const text = el.json.value;
      if (text.length > limit.bytes) { el.json.value = ''; forget(); ui.error('Scene not taken: ' + limit.message); }
      else if (text.length > BOX_SHOWN) hold(text, 'Typed');
      else if (text !== '') forget();
    });
    el.loadJson.addEventListener('click', function () {
      const text = heldText !== null && el.json.value === '' ? heldText : el.json.value;
      try { h.loadJson(text); } catch (e) { /* shown in the banner */ }
    });
    el.showJson.addEventListener('click', function () {
      const text = h.currentJson();
      if (text.length > BOX_SHOWN) hold(text, 'The current scene is');
      else { forget(); el.json.value = text; }
    });
    $('charts-on').addEventListener('change', function () { h.charts($('charts-on').checked); });
    $('btn-cut').addEventListener('click', function () { h.cutTool(); });
    $('btn-replay').addEventListener('click', function () { h.replay(); });
    $('btn-export').addEventListener('click', function () { h.exportFile(); });
    $('btn-picture').addEventListener('click', function () { h.picture(); });
    $('btn-video').addEventListener('click', function () { h.video(); });
    $('btn-link').addEventListener('click', function () { h.copyLink(); });
    $('btn-open').addEventListener('click', function () { el.fileInput.click(); });
    el.fileInput.addEventListener('change', function () {
      const f = el.fileInput.files && el.fileInput.files[0];
      el.fileInput.value = '';       // choosing the same file again fires change again
      if (f) h.openFile(f);
    });
    // A file dropped anywhere on the page opens (the browser would otherwise navigate to it).
    function hasFiles(e) {
      const t = e.dataTransfer && e.dataTransfer.types;
      return !!t && Array.prototype.indexOf.call(t, 'Files') >= 0;
    }
    window.addEventListener('dragover', function (e) {
      if (!hasFiles(e)) return;
      e.preventDefault();
      e.dataTransfer.dropEffect = 'copy';
      document.body.classList.add('dropping');
    });
    window.addEventListener('dragleave', function (e) {
      if (e.relatedTarget === null) document.body.classList.remove('dropping');
    });
    window.addEventListener('drop', function (e) {
      document.body.classList.remove('dropping');
      if (!hasFiles(e)) return;
      e.preventDefault();
      const f = e.dataTransfer.files[0];
      if (f) h.openFile(f);
    });

    // Shortcuts work wherever focus is, except where the key types text or works the
    // focused control: a text field takes every key; a button, a summary or a link takes
    // Space and Enter (Space opens the Scene JSON box); a radio group or a menu keeps its
    // arrow keys. While the help is open it is modal: it takes the keys, Esc or H closes it.
    window.addEventListener('keydown', function (e) {
      const k = e.key;
      if (helpOpen) {
        if (k === 'Escape' || k === 'h' || k === 'H' || k === '?') { ui.showHelp(false); e.preventDefault(); }
        else if (k === 'Tab') trapFocus(e);
        else if (k !== 'Enter' && !(k === ' ' && e.target === el.helpClose)) e.preventDefault();
        return;
      }
      if (k === 'Escape') return;
      if (e.ctrlKey || e.metaKey || e.altKey) return;
      if (ownsKey(e.target, k)) return;
      let handled = true;
      if (k === ' ') h.pause();
      else if (k === 's' || k === 'S' || k === 'ArrowRight') h.step();
      else if (k === 'r' || k === 'R') h.reset();
      else if (k === 'c' || k === 'C') h.mode(null);
      else if (k === 'a' || k === 'A') h.scaleMode(null);
      else if (k === 'h' || k === 'H' || k === '?') ui.showHelp(true);
      else if (Object.prototype.hasOwnProperty.call(PRESET_KEYS, k)) h.preset(PRESET_KEYS[k]);
      else if (Object.prototype.hasOwnProperty.call(ACTION_KEYS, k.toLowerCase())) h[ACTION_KEYS[k.toLowerCase()]]();
      else if (k === 'o' || k === 'O') el.fileInput.click();
      else if (k === 'x' || k === 'X') h.cutTool();
      else handled = false;
      if (handled) e.preventDefault();
    });

    function trapFocus(e) {
      // The help has one focusable control: Tab stays on it.
      e.preventDefault();
      el.helpClose.focus();
    }

    const ui = {
      // Every field but the one typed in and not yet committed (above).
      setParams: function (p) {
        shown = p;
        fieldKeys.forEach(function (key) {
          if (p[key] === undefined || $(key) === typed) return;
          // a key whose 0 means none (tearing): the field shows its placeholder, "off"
          $(key).value = LIMITS[key].off && !(p[key] > 0) ? '' : String(p[key]);
        });
        if (p.material !== undefined) $('material').value = p.material;
      },
      setCutTool: function (on) {
        $('btn-cut').setAttribute('aria-pressed', on ? 'true' : 'false');
        $('btn-cut').classList.toggle('on', on);
      },
      setPreset: function (name) { el.preset.value = name; },
      // The Video button says whether it records.
      setVideo: function (on) {
        $('btn-video').textContent = on ? 'Stop video' : 'Video';
        $('btn-video').setAttribute('aria-pressed', on ? 'true' : 'false');
      },
      // The live charts shown or not, and their box checked to say so.
      setCharts: function (on) { $('charts-on').checked = on; $('charts').hidden = !on; },
      // The help's words for the Auto scale's floor (readouts.js AUTO_FLOOR).
      setAutoFloor: function (v) { $('auto-floor').textContent = String(v); },
      setSolver: function (name) { $('solver').value = name; },
      setPaused: function (paused) {
        el.pause.textContent = paused ? 'Resume' : 'Pause';
        el.paused.hidden = !paused;
      },
      setMode: function (mode) {
        checkRadio('mode', mode);
        el.legend.classList.toggle('stress', mode === 'stress');
      },
      setScale: function (scaleMode, fullScale) {
        checkRadio('scale', scaleMode);
        el.fullScale.value = String(fullScale);
        el.fullScale.disabled = scaleMode !== 'fixed';
      },
      // Ticks in the quantity the title names; the title says what the colours are, what the
      // scale's top is (the frame's maximum, the auto floor, or the fixed full scale), and the
      // note under it the fabric and how balanced the solver's forces are (readouts.js).
      setLegend: function (scale, top, name, note) {
        el.legendTitle.textContent = name + ' ' + LEGEND_TOP[top];
        el.legendNote.textContent = note;
        el.legendLo.textContent = '0';
        el.legendMid.textContent = fmt(scale / 2, 4);
        el.legendHi.textContent = fmt(scale, 4);
      },
      setReadouts: function (r) {
        el.sim.textContent = fmt(r.simMs, 2);
        el.render.textContent = fmt(r.renderMs, 2);
        el.fps.textContent = fmt(r.fps, 0);
        el.rms.textContent = fmt(r.rms, 4);
        el.max.textContent = fmt(r.max, 4);
        el.size.textContent = r.size;
      },
      // The recording's state, and a replay's progress (frame k of F) while one plays.
      setRecording: function (r) {
        el.recStatus.textContent = r.full
          ? 'recording full at frame ' + r.complete + ' (' + r.actions + ' actions): later gestures are not kept'
          : 'recording · ' + r.frames + ' frames · ' + r.actions + ' action' + (r.actions === 1 ? '' : 's');
        el.replay.hidden = r.replayEnd < 0;
        if (r.replayEnd >= 0) {
          el.replayFrame.textContent = String(r.frames);
          el.replayEnd.textContent = String(r.replayEnd);
        }
      },
      // A short-lived note under the inputs (clamped values).
      note: function (msg) {
        el.note.textContent = msg;
        el.note.hidden = !msg;
        clearTimeout(noteTimer);
        if (msg) noteTimer = setTimeout(function () { el.note.hidden = true; }, 6000);
      },
      // An error may name what it is about (`about`), so that what ends that condition clears
      // it and nothing else (a later error replaces it, and its own end then clears nothing).
      error: function (msg, about) {
        el.bannerText.textContent = msg; el.banner.hidden = false; errorAbout = about || '';
      },
      // clearError(): any error; clearError(about): that one's; clearError(undefined, keep):
      // any but that one.
      clearError: function (about, keep) {
        if (about !== undefined && about !== errorAbout) return;
        if (keep !== undefined && keep === errorAbout) return;
        hide(el.banner); el.bannerText.textContent = ''; errorAbout = '';
      },
      errorText: function () { return el.banner.hidden ? '' : el.bannerText.textContent; },
      noteText: function () { return el.note.hidden ? '' : el.note.textContent; },
      fatal: function (msg) { el.fatal.textContent = msg; el.fatal.hidden = !msg; },
      // The help is modal: focus goes into it, and back where it was when it closes.
      showHelp: function (show) {
        if (show === helpOpen) return;
        helpOpen = show;
        if (show) helpReturn = document.activeElement;
        if (show) {
          el.helpBox.hidden = false;
          // Focus without scrolling to the Close button at the card's end: the card opens at
          // its title (on a phone the card scrolls, and focus() scrolled it to the bottom).
          el.helpClose.focus({ preventScroll: true });
          const card = el.helpBox.querySelector('.card');
          if (card) card.scrollTop = 0;
          return;
        }
        hide(el.helpBox);
        if (helpReturn && helpReturn !== document.body && helpReturn.focus) helpReturn.focus();
        helpReturn = null;
      },
    };
    return ui;
  }

  return { create: create, fmt: fmt };
})();
