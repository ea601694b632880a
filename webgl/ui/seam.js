// The test seam: window.clothApp, what the tests and the console drive the page by. It reads
// the app's state through the handle app.js publishes and acts only through the app's own
// functions (the same a person's controls call), so what a test sees is what the page does.
// Besides it, the modules the tests and the benchmark call directly (bench/harness.js steps
// frames with the runner the page uses), published here and nowhere else: no page module
// reads a window.cloth* name.
import { clothCore } from '../sim/core.js';
import { clothScenes } from '../sim/scenes.js';
import { clothRunner } from '../sim/runner.js';
import { clothRenderer } from '../draw/renderer.js';
import { clothCharts } from '../draw/charts.js';
import { clothCapture } from '../draw/capture.js';
import { clothGestures } from '../input/gestures.js';
import { clothInput } from '../input/input.js';
import { clothReadouts } from './readouts.js';

Object.assign(window, { clothCore, clothScenes, clothRunner, clothRenderer, clothCharts, clothCapture,
                        clothGestures, clothInput, clothReadouts });

export const clothSeam = (function () {
  // app: {state(), sess(), canvas, renderer, charts, ui, runner, session, bladeOn(),
  // allAsleep(), autoFloor, render, and the actions listed in clothApp below}.
  function publish(app) {
    const canvas = app.canvas, renderer = app.renderer;

    // {positions: [[x, y]...] metres, screen: [[clientX, clientY]...], pinned, held, hands} of
    // panel i; hands[k]: for a held vertex, where its hand is (clientX, clientY: the pointer's
    // point in the cloth, which a hand of finite strength takes its vertex toward), else null.
    function stateOf(i) {
      const p = app.state().panels[i], c = p.cloth, n = c.n_verts, pos = c.pos;
      const r = canvas.getBoundingClientRect();
      const out = { positions: [], screen: [], pinned: [], held: [], hands: [] };
      for (let k = 0; k < n; k++) {
        const x = pos[2 * k], y = pos[2 * k + 1];
        out.positions.push([x, y]);
        if (renderer.ok) {
          const q = p.draw.toCanvas(x, y);
          out.screen.push([r.left + q[0], r.top + q[1]]);
        }
        out.pinned.push(c.pinned[k] !== 0);
        out.held.push(c.held[k] !== 0);
        if (c.held[k] !== 0 && renderer.ok) {
          const q = p.draw.toCanvas(c.target[2 * k], c.target[2 * k + 1]);
          out.hands.push([r.left + q[0], r.top + q[1]]);
        } else {
          out.hands.push(null);
        }
      }
      return out;
    }

    window.clothApp = {
      // The first panel's (the only one outside compare mode).
      state: function () { return stateOf(0); },
      // A world point of panel i (default 0) in client px (where a pointer would press it).
      clientOf: function (x, y, i) {
        const p = app.state().panels[i || 0], r = canvas.getBoundingClientRect(), q = p.draw.toCanvas(x, y);
        return [r.left + q[0], r.top + q[1]];
      },
      // Panel i's obstacles: [{at: [x, y] (where the physics has it), to: [x, y] (where it is
      // going), half: [hx, hy], shape}] .
      obstacles: function (i) {
        const c = app.state().panels[i || 0].cloth, out = [];
        for (let j = 0; j < c.n_obstacles; j++) {
          out.push({ at: [c.obstacle_at[2 * j], c.obstacle_at[2 * j + 1]], to: [c.obstacle_to[2 * j], c.obstacle_to[2 * j + 1]],
                     half: [c.obstacle_half[2 * j], c.obstacle_half[2 * j + 1]], shape: c.obstacle_shape[j] });
        }
        return out;
      },
      setPaused: app.setPaused,
      advance: app.advance,
      // The recording since the last load or reset, as scene JSON text with `frames`.
      recording: app.recordingText,
      // A Promise of the link that replays the recording.
      link: app.link,
      replay: function () { app.replay(); return true; },
      exportRecording: app.exportRecording,
      // Compare mode: an array of objects of scene keys, one per panel ([] leaves it).
      compare: function (list) { return app.setCompare(list); },
      // Per panel: {label, scene (the panel's full scene JSON text), positions, screen,
      // rms_strain, max_strain, sim_ms}, and pinned, held, max_value, high_value (the edges'
      // value Auto scales the strain colours to), imbalance, max_stress.
      panels: function () {
        const state = app.state();
        return state.panels.map(function (p, i) {
          const st = stateOf(i);
          const obj = Object.assign({}, state.sceneObj);
          delete obj.compare;
          if (state.compare.length) Object.assign(obj, state.compare[i]);
          return { label: app.runner.label(p.cloth), scene: JSON.stringify(obj), positions: st.positions,
                   screen: st.screen, rms_strain: p.cloth.rms_strain, max_strain: p.cloth.max_strain,
                   sim_ms: p.simMs, pinned: st.pinned, held: st.held, hands: st.hands, max_value: p.cloth.max_value,
                   high_value: p.cloth.high_value, imbalance: p.cloth.imbalance,
                   max_stress: p.cloth.max_stress };
        });
      },
      setColorMode: app.setColorMode,
      loadScene: app.loadScene,
      // Extras for tests and the console.
      setScaleMode: function (mode, fullScale) {
        if (fullScale !== undefined) app.setFullScale(fullScale);
        app.setScaleMode(mode);
      },
      usePreset: function (name) { app.usePreset(name); return true; },
      setParam: app.setParam,
      setSolver: app.setSolver,
      setCutTool: app.setCutTool,
      reset: app.reset,
      cloth: function () { return app.state().cloth; },
      // What the charts wrote at their last draw: [text, x, y, width, box x, y, w, h].
      chartTexts: function () { return app.charts.written(); },
      // RGBA at client coordinates, read right after a fresh draw.
      pixels: function (points) {
        app.render();
        const r = canvas.getBoundingClientRect();
        return points.map(function (p) { return renderer.readPixel(p[0] - r.left, p[1] - r.top); });
      },
      info: function () {
        const state = app.state(), sess = app.sess(), session = app.session, ui = app.ui;
        return {
          webgl: renderer.ok ? renderer.version : 0, lost: !!renderer.lost, restores: renderer.restores || 0,
          relayouts: state.relayouts,
          drawCalls: renderer.drawCalls || 0, paused: state.paused, mode: state.mode, scaleMode: state.scaleMode,
          scale: state.scale, fullScale: state.fullScale, autoFloor: app.autoFloor, frames: sess ? sess.frame : 0,
          preset: state.preset, params: state.params,
          asleep: !!(state.cloth && app.allAsleep()), renders: state.renders,
          fps: state.fps, fpsAt: state.fpsAt, renderMs: state.renderMs,
          rects: state.rects.map(function (r) { return [r.x, r.y, r.w, r.h]; }),
          replay: { playing: sess.replay_end >= 0, end: sess.replay_end, ended: sess.replay_ended },
          linkPending: !!state.linkPending, panels: state.panels.length,
          simMs: state.panels.length ? state.panels[0].simMs : NaN, chartLatest: app.charts.latest(0),
          edges: state.cloth ? state.cloth.n_edges : 0, broken: state.cloth ? state.cloth.broken : 0,
          cutTool: app.bladeOn(),
          recorded: session.recordingCount(sess), recordingFull: session.recordingFull(sess),
          error: ui.errorText(), note: ui.noteText(), scene: state.sceneText,
          canvas: [canvas.width, canvas.height], dpr: window.devicePixelRatio || 1,
        };
      },
    };
  }

  return { publish: publish };
})();
