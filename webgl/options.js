// The page's URL options (?preset=, ?paused=, ?webgl=): parsed once at start, each
// value checked against the values it can take. An unknown option or value is
// never silently ignored: it comes back as a note, and the option keeps its default.
// Lookups go through own properties only, so `?preset=toString` is just unknown.
'use strict';

window.clothOptions = (function () {
  function own(obj, key) { return Object.prototype.hasOwnProperty.call(obj, key); }

  const FLAGS = { '1': true, 'true': true, 'yes': true, '0': false, 'false': false, 'no': false };
  const WEBGL = { auto: 'auto', '2': 'auto', '1': '1', '0': '0', off: '0', none: '0' };

  // parse(search, presets) -> {preset, paused, webgl, notes: [text...]}
  function parse(search, presets) {
    const q = new URLSearchParams(search);
    const out = { preset: 'curtain', paused: false, webgl: 'auto', notes: [] };
    function unknown(key, value, allowed) {
      out.notes.push('URL option ' + key + '=' + JSON.stringify(value).slice(0, 40) +
                     ' is not one of ' + allowed + '; using the default');
    }
    q.forEach(function (value, key) {
      if (key === 'preset') {
        if (own(presets, value)) out.preset = value;
        else unknown(key, value, Object.keys(presets).join(', '));
      } else if (key === 'paused') {
        if (own(FLAGS, value.toLowerCase())) out.paused = FLAGS[value.toLowerCase()];
        else unknown(key, value, '1, 0, true, false');
      } else if (key === 'webgl') {
        if (own(WEBGL, value.toLowerCase())) out.webgl = WEBGL[value.toLowerCase()];
        else unknown(key, value, 'auto, 2, 1, 0');
      } else {
        out.notes.push('Unknown URL option "' + key.slice(0, 40) + '" ignored (known: preset, paused, webgl)');
      }
    });
    return out;
  }

  return { parse: parse, own: own };
})();
