// The page's URL options (?preset=, ?paused=, ?webgl=, ?worker=): parsed once at start, each
// value checked against the values it can take. An unknown option or value is
// never silently ignored: it comes back as a note, and the option keeps its default.
// Lookups go through own properties only, so `?preset=toString` is just unknown.

export const clothOptions = (function () {
  function own(obj, key) { return Object.prototype.hasOwnProperty.call(obj, key); }

  const FLAGS = { '1': true, 'true': true, 'yes': true, '0': false, 'false': false, 'no': false };
  const WEBGL = { auto: 'auto', '2': 'auto', '1': '1', '0': '0', off: '0', none: '0' };

  const MAX_NOTES = 4;

  // parse(search, presets) -> {preset, paused, webgl, worker, notes: [text...]} (worker: run
  // the simulation in a Web Worker, the default; 0 runs it on the page's own thread, which the
  // tests' synchronous seam drives). Values are matched
  // without regard to case; an option given twice says so (the last one counts); at most
  // MAX_NOTES notes, then how many more.
  function parse(search, presets) {
    const q = new URLSearchParams(search);
    const out = { preset: Object.keys(presets)[0], paused: false, webgl: 'auto', worker: true, notes: [] };
    const notes = [];
    const seen = {};
    function unknown(key, value, allowed) {
      notes.push('URL option ' + key + '=' + JSON.stringify(value).slice(0, 40) +
                 ' is not one of ' + allowed + '; using the default');
    }
    q.forEach(function (value, key) {
      const v = value.toLowerCase();
      if (own(seen, key)) notes.push('URL option ' + key.slice(0, 40) + ' is given more than once; the last one counts');
      seen[key] = true;
      if (key === 'preset') {
        if (own(presets, v)) out.preset = v;
        else unknown(key, value, Object.keys(presets).join(', '));
      } else if (key === 'paused') {
        if (own(FLAGS, v)) out.paused = FLAGS[v];
        else unknown(key, value, '1, 0, true, false');
      } else if (key === 'webgl') {
        if (own(WEBGL, v)) out.webgl = WEBGL[v];
        else unknown(key, value, 'auto, 2, 1, 0');
      } else if (key === 'worker') {
        if (own(FLAGS, v)) out.worker = FLAGS[v];
        else unknown(key, value, '1, 0, true, false');
      } else {
        notes.push('Unknown URL option ' + JSON.stringify(key).slice(0, 40) + ' ignored (known: preset, paused, webgl, worker)');
      }
    });
    out.notes = notes.slice(0, MAX_NOTES);
    if (notes.length > MAX_NOTES) out.notes.push('and ' + (notes.length - MAX_NOTES) + ' more about the URL');
    return out;
  }

  return { parse: parse, own: own };
})();
