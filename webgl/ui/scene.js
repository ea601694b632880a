// The scene that runs, as the page holds it: its text and object, the preset it came from (or
// 'custom'), its view, its compare list, the settings the panel shows, and what the page said
// of it. Loading one (a preset, a file, a link, a new grid, a compare list) opens it in the
// panels (sim/panels.js) and tells the app, which lays out and draws the new panels.
import { clothCore } from '../sim/core.js';
import { clothParams } from '../sim/params.js';
import { clothScenes } from '../sim/scenes.js';
import { clothShare } from '../sim/share.js';
import { clothSettings } from './settings.js';

export const clothScene = (function () {
  const scenes = clothScenes;

  // app: {panels, ui, compareUI, gestures() (gestures.js), opened() (the panels are new: lay
  // them out), changed() (draw again), render(), setPaused(on), settings() (settings.js)}.
  function create(app) {
    const panels = app.panels, ui = app.ui, compareUI = app.compareUI;
    let text = '', obj = null, preset = null, view = null, compare = [], params = null;
    let pinEdits = {};         // vertex -> pinned: the pins a person set (true) or removed (false)
    let loadNote = '';         // what load() said of the scene it loaded ('' for nothing)
    let replaying = false;     // a replay was playing when the last note about it was said

    // Load scene JSON text. On a bad scene: show the message, keep the old scene running, and
    // throw an Error with the core's message. holds: [{id, k}] pointers that go on holding
    // vertex k of the new cloth (a grid change); any other pointer lets go. edits: the pins a
    // person set or removed that the new scene carries over (a grid change), {} otherwise.
    function load(newText, name, shown, holds, edits) {
      let parsed;
      try {
        // The core checks the scene (its messages, as in the CLI); then the page's limits,
        // before anything is built: a scene beyond them would take seconds a frame.
        clothCore.parseScene(newText);
        parsed = JSON.parse(newText);
        const limit = clothParams.limitOf(parsed);
        if (limit) throw new Error(limit);
        panels.open(newText);
      } catch (e) {
        const msg = e && e.message ? e.message : String(e);
        ui.error('Scene not loaded: ' + msg + (obj ? ' (the previous scene keeps running)' : ''));
        throw new Error(msg);
      }
      ui.clearError(undefined, 'context');   // a load ends its own errors, not a lost context's
      const gestures = app.gestures();
      gestures.releaseAll(holds || []);
      compare = Array.isArray(parsed.compare) ? parsed.compare.map(function (o) { return Object.assign({}, o); }) : [];
      pinEdits = edits || {};
      text = newText; obj = parsed; preset = name;
      view = shown || scenes.viewFor(obj);
      // The scene's own actions of frame 0 came before any frame (the session applied them): a
      // pointer kept over a grid change lets go of a vertex the script took.
      gestures.held().forEach(function (h) { if (panels.held(h.k)) gestures.forget(h.k); });
      compareUI.render(compare);
      app.opened();
      // The pointers that kept a vertex hold it again, where it now is, keeping on with their
      // pointer from here (recorded as grabs, at frame 0 of the new recording).
      gestures.regrab();
      ui.setPreset(name);
      showSettings();
      app.render();
      // What the page says of the new scene, all of it in one note (one said after another
      // replaced it: a heavy scene of an older model said only that it was old).
      const work = scenes.workOf(obj) * Math.max(1, compare.length);
      loadNote = (work > scenes.REAL_TIME_WORK ? [scenes.slowNote(work)] : []).concat(panels.openNotes()).join('; ');
      if (loadNote) ui.note(loadNote);
      replaying = panels.replayEnd() > 0;
      if (panels.replayEnd() === 0) { panels.atReplayEnd(); app.setPaused(true); }
      else if (panels.replayEnd() > 0) app.setPaused(false);
    }

    // The script's actions ran: a scripted grab took its vertex from a person's hand (so the
    // pointer lets go of it here too); a scripted set changes what the settings panel and the
    // compare editor show.
    function scripted() {
      const gestures = app.gestures();
      gestures.held().forEach(function (h) { if (!panels.byPerson(h.k)) gestures.forget(h.k); });
      showSettings();
      app.settings().followSets();
    }

    // The settings panel shows what the scene's settings are now (the session's base cloth's).
    function showSettings() {
      params = clothSettings.paramsOf(panels.baseScene());
      ui.setParams(params);
      ui.setSolver(params.solver);
    }

    // A person acted (a gesture, a setting; the session took over a replay that was playing,
    // cutting its script at this frame): a replay that had ended runs again.
    function acted() {
      if (panels.resumed()) app.setPaused(false);
      if (replaying && panels.replayEnd() < 0) {
        replaying = false;
        ui.note('You took over the replay at frame ' + panels.frame() + ': recording from here');
      }
      app.changed();
    }

    // A person's gestures (gestures.js's act): each applied at once in every panel and
    // recorded at the current frame (panels.js); a person acting during a replay takes over.
    const act = {
      grab: function (k, x, y) { panels.grab(k, x, y); acted(); },
      move: function (k, x, y) { if (panels.move(k, x, y)) acted(); },
      release: function (k) { if (panels.release(k)) acted(); },
      togglePin: function (k) { pinEdits[k] = panels.snap(0).pinned[k] === 0; panels.togglePin(k); acted(); },
      cut: function (x0, y0, x1, y1) { if (panels.cut(x0, y0, x1, y1)) acted(); },
      obstacle: function (j, x, y) { if (panels.obstacle(j, x, y)) acted(); },
    };

    // The replay reached its last frame.
    function replayEnded() { replaying = false; }

    // A preset keeps compare mode: the same panels run the new scene.
    function usePreset(name, given) {
      const made = scenes.make(name, given || scenes.defaults(name));
      if (compare.length) made.scene.compare = compare;
      ui.note('');
      load(JSON.stringify(made.scene), name, made.view);
    }

    // A new start: what the notes said of the old one is over.
    function reset() { ui.note(''); load(text, preset, view); }

    // Scene JSON text pasted or typed: decoded as a file of the same bytes (share.js: its size
    // checked), then loaded; throws what the banner says.
    function paste(given) {
      let checked;
      try {
        checked = clothShare.fromText(given);
      } catch (e) {
        ui.error('Scene not loaded: ' + e.message + (obj ? ' (the previous scene keeps running)' : ''));
        throw e;
      }
      loadScene(checked);
    }

    function loadScene(given) {
      ui.note('');      // what the notes said of the old scene is over (load may say something new)
      load(typeof given === 'string' ? given : JSON.stringify(given), 'custom', null);
      return true;
    }

    // Compare mode: the current scene (its grid, pins, script and settings) with a new compare
    // list, from frame 0 and a new recording; [] leaves compare mode.
    function setCompare(list, note) {
      if (!Array.isArray(list)) throw new Error('compare needs an array of objects of scene keys');
      const next = Object.assign({}, obj);
      delete next.frames;
      if (list.length) next.compare = list; else delete next.compare;
      try {
        load(JSON.stringify(next), preset, view);
      } catch (e) {
        compareUI.render(compare);   // the banner says why; the old panels run on
        return false;
      }
      ui.note(note || (list.length ? 'Comparing ' + list.length + ' panels under the same hands, from frame 0' : ''));
      return true;
    }

    return {
      load: load, scripted: scripted, acted: acted, act: act, replayEnded: replayEnded, usePreset: usePreset, reset: reset,
      loadScene: loadScene, paste: paste, setCompare: setCompare,
      text: function () { return text; }, obj: function () { return obj; }, preset: function () { return preset; },
      view: function () { return view; }, compare: function () { return compare; },
      params: function () { return params; }, pinEdits: function () { return pinEdits; },
      loadNote: function () { return loadNote; },
      // Compare mode now runs this list (settings.js followSets).
      followed: function (list) { compare = list; compareUI.render(list); },
      // The scene object the running cloth now is (a setting applied): Reset restarts with it.
      retuned: function (next) { obj = next; text = JSON.stringify(next); showSettings(); app.changed(); },
    };
  }

  return { create: create };
})();
