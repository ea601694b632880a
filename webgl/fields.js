// The panel's and the compare editor's number fields: one kind of field for every number a
// person types. Text fields, not type=number: a number field rewrites what is typed before
// the page sees it (a typographic minus dropped: -5 became 5; 5,5 became 55; 0x10, 10), and
// reports letters as empty. The page reads the text once, with scenes.js readNumber, and
// says what it did. ArrowUp and ArrowDown step by the field's step, within its range.
'use strict';

window.clothFields = (function () {
  const LIMITS = window.clothScenes.LIMITS;

  // What a field for LIMITS[key] is called: the key's label and unit (cloth/scene.py KEYS).
  function caption(key) {
    const lim = LIMITS[key];
    return lim.label + (lim.unit ? ' (' + lim.unit + ')' : '');
  }

  // Make `input` the number field for LIMITS[key]; onText(text) gets what was typed, on
  // change and on each arrow step. A <label> around it is captioned from the key.
  function attach(input, key, onText) {
    const lim = LIMITS[key];
    const around = input.parentNode;
    if (around && around.tagName === 'LABEL' && around.firstChild && around.firstChild.nodeType === 3) {
      around.firstChild.nodeValue = caption(key) + ' ';
    }
    input.type = 'text';
    input.inputMode = lim.int ? 'numeric' : (lim.min < 0 ? 'text' : 'decimal');   // a phone's decimal pad has no minus
    input.autocomplete = 'off';
    input.spellcheck = false;
    input.setAttribute('autocorrect', 'off');
    input.title = input.title || lim.label + ': ' + lim.min + ' to ' + lim.max;
    input.addEventListener('change', function () { onText(input.value); });
    input.addEventListener('keydown', function (e) {
      if (e.key !== 'ArrowUp' && e.key !== 'ArrowDown') return;
      const r = window.clothScenes.readNumber(input.value);
      if (r.value === null) return;
      e.preventDefault();
      let v = r.value + (e.key === 'ArrowUp' ? lim.step : -lim.step);
      v = Math.min(lim.max, Math.max(lim.min, Number(v.toPrecision(12))));     // 0.1 + 0.2 shows as 0.3
      input.value = String(v);
      onText(input.value);
    });
  }

  return { attach: attach, caption: caption };
})();
