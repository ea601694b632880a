// The panel's and the compare editor's number fields: one kind of field for every number a
// person types. Text fields, not type=number: a number field rewrites what is typed before
// the page sees it (a typographic minus dropped: -5 became 5; 5,5 became 55; 0x10, 10), and
// reports letters as empty. The page reads the text once, with scenes.js readNumber, and
// says what it did. ArrowUp and ArrowDown step by the field's step, within its range; from an empty field, from
// what it stands for (a key whose 0 means none steps up from none to its least value).
import { clothScenes } from '../sim/scenes.js';

export const clothFields = (function () {
  const LIMITS = clothScenes.LIMITS;

  // What a field for LIMITS[key] is called: the key's label and unit (cloth/scene.py KEYS).
  function caption(key) {
    const lim = LIMITS[key];
    return lim.label + (lim.unit ? ' (' + lim.unit + ')' : '');
  }

  // Make `input` the number field for LIMITS[key]; onText(text) gets what was typed, on
  // change and on each arrow step. A <label> around it is captioned from the key.
  // emptyValue(): the number an empty field stands for (the compare editor's: the scene's);
  // without it, an empty or `off` field of a key whose 0 means none stands for 0.
  function attach(input, key, onText, emptyValue) {
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
      const text = input.value.trim().toLowerCase(), up = e.key === 'ArrowUp';
      let from = clothScenes.readNumber(input.value).value;
      if (from === null && (text === '' || (lim.off && text === 'off'))) {
        from = emptyValue ? emptyValue() : (lim.off ? 0 : null);
      }
      if (typeof from !== 'number' || !Number.isFinite(from)) return;
      if (lim.off && from === 0 && !up) return;            // below none is none
      e.preventDefault();
      let v = lim.off && from === 0 ? lim.min : from + (up ? lim.step : -lim.step);   // none steps up to the least
      v = Math.min(lim.max, Math.max(lim.min, Number(v.toPrecision(12))));     // 0.1 + 0.2 shows as 0.3
      input.value = String(v);
      onText(input.value);
    });
  }

  return { attach: attach, caption: caption };
})();
