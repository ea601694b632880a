// The colours' settings, owned here: what the edges show (the membrane's strain, or the seed's
// node stress) and the top of their scale (Auto's, or a fixed strain the person typed).
import { clothScenes } from '../sim/scenes.js';

export const clothColours = (function () {
  const MODES = ['strain', 'stress'];
  const SCALES = ['auto', 'fixed'];
  const FULL_SCALE = 0.05;     // the fixed scale until a person types one

  // ui (ui.js), changed() (the picture is to be drawn again).
  function create(ui, changed) {
    let mode = MODES[0], scaleMode = SCALES[0], fullScale = FULL_SCALE;

    function show() { ui.setMode(mode); ui.setScale(scaleMode, fullScale); }

    function setMode(m) {
      if (MODES.indexOf(m) < 0) throw new Error("colour mode must be 'strain' or 'stress'");
      mode = m;
      ui.setMode(mode);
      changed();
    }

    function setScaleMode(m) {
      if (SCALES.indexOf(m) < 0) throw new Error("scale must be 'auto' or 'fixed'");
      scaleMode = m;
      ui.setScale(scaleMode, fullScale);
      changed();
    }

    // A typed full scale: clamped to its limits (scenes.js LIMITS) with a note, or refused.
    function setFullScale(raw) {
      const c = clothScenes.clamp('fullScale', raw);
      ui.note(c.note);
      if (c.value !== null) fullScale = c.value;
      ui.setScale(scaleMode, fullScale);
      changed();
    }

    return {
      show: show, setMode: setMode, setScaleMode: setScaleMode, setFullScale: setFullScale,
      mode: function () { return mode; },
      scaleMode: function () { return scaleMode; },
      fullScale: function () { return fullScale; },
      // The other mode, the other scale (the buttons that toggle them).
      otherMode: function () { return mode === MODES[0] ? MODES[1] : MODES[0]; },
      otherScale: function () { return scaleMode === SCALES[0] ? SCALES[1] : SCALES[0]; },
    };
  }

  return { create: create };
})();
