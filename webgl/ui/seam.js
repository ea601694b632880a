// The test seam: window.clothApp, what the tests and the console drive the page by. It reads
// what the app runs through the getters app.js publishes and acts only through the app's own
// functions (the same a person's controls call), so what a test sees is what the page does.
// Besides it, the modules the tests and the benchmark call directly (bench/harness.js steps
// frames with the runner the page uses), published here and nowhere else: no page module
// reads a window.cloth* name.
import { clothCore } from '../sim/core.js';
import { clothScenes } from '../sim/scenes.js';
import { clothRunner } from '../sim/runner.js';
import { clothClock } from '../sim/clock.js';
import { clothRenderer } from '../draw/renderer.js';
import { clothCharts } from '../draw/charts.js';
import { clothCapture } from '../draw/capture.js';
import { clothGestures } from '../input/gestures.js';
import { clothInput } from '../input/input.js';
import { clothReadouts } from './readouts.js';

Object.assign(window, { clothCore, clothScenes, clothRunner, clothClock, clothRenderer, clothCharts, clothCapture,
                        clothGestures, clothInput, clothReadouts });

export const clothSeam = (function () {
  // app: {panels (sim/panels.js), views (draw/views.js), scene (ui/scene.js), canvas,
  // renderer, charts, ui, painter, colours, files, bladeOn(), status() (a copy of the loop's
  // own: paused, relayouts, fps, fpsAt, simMs), and the actions listed in clothApp below}.
  function publish(app) {
    const canvas = app.canvas, renderer = app.renderer, panels = app.panels, views = app.views, scene = app.scene;

    // {positions: [[x, y]...] metres, screen: [[clientX, clientY]...], pinned, held, hands} of
    // panel i; hands[k]: for a held vertex, where its hand is (clientX, clientY: the pointer's
    // point in the cloth, which a hand of finite strength takes its vertex toward), else null.
    function stateOf(i) {
      panels.refresh();
      const c = panels.snap(i), n = c.n_verts, pos = c.pos, r = canvas.getBoundingClientRect();
      function client(x, y) { const q = views.toCanvas(i, x, y); return [r.left + q[0], r.top + q[1]]; }
      const out = { positions: [], screen: [], pinned: [], held: [], hands: [] };
      for (let k = 0; k < n; k++) {
        const x = pos[2 * k], y = pos[2 * k + 1];
        out.positions.push([x, y]);
        if (renderer.ok) out.screen.push(client(x, y));
        out.pinned.push(c.pinned[k] !== 0);
        out.held.push(c.held[k] !== 0);
        out.hands.push(c.held[k] !== 0 && renderer.ok ? client(c.target[2 * k], c.target[2 * k + 1]) : null);
      }
      return out;
    }

    window.clothApp = {
      // The first panel's (the only one outside compare mode).
      state: function () { return stateOf(0); },
      // A world point of panel i (default 0) in client px (where a pointer would press it).
      clientOf: function (x, y, i) {
        const r = canvas.getBoundingClientRect(), q = views.toCanvas(i || 0, x, y);
        return [r.left + q[0], r.top + q[1]];
      },
      // Panel i's obstacles: [{at: [x, y] (where the physics has it), to: [x, y] (where it is
      // going), half: [hx, hy], shape}] .
      obstacles: function (i) {
        const c = panels.cloth(i || 0), out = [];
        for (let j = 0; j < c.n_obstacles; j++) {
          out.push({ at: [c.obstacle_at[2 * j], c.obstacle_at[2 * j + 1]], to: [c.obstacle_to[2 * j], c.obstacle_to[2 * j + 1]],
                     half: [c.obstacle_half[2 * j], c.obstacle_half[2 * j + 1]], shape: c.obstacle_shape[j] });
        }
        return out;
      },
      setPaused: app.setPaused,
      advance: app.advance,
      // The recording since the last load or reset, as scene JSON text with `frames`.
      recording: function () {
        return panels.remote ? new Promise(function (resolve) { panels.recording(resolve); }) : panels.recordingText();
      },
      // A Promise of the link that replays the recording.
      link: app.files.link,
      replay: function () { app.files.replay(); return true; },
      exportRecording: app.files.exportRecording,
      // Compare mode: an array of objects of scene keys, one per panel ([] leaves it).
      compare: function (list) { return scene.setCompare(list); },
      // Per panel: {label, scene (the panel's full scene JSON text), positions, screen,
      // rms_strain, max_strain, sim_ms}, and pinned, held, max_value, high_value (the edges'
      // value Auto scales the strain colours to), imbalance, max_stress.
      panels: function () {
        const st = app.status(), compare = scene.compare();
        return views.list().map(function (v, i) {
          const one = stateOf(i), c = panels.cloth(i);
          const obj = Object.assign({}, scene.obj());
          delete obj.compare;
          if (compare.length) Object.assign(obj, compare[i]);
          return { label: panels.label(i), scene: JSON.stringify(obj), positions: one.positions,
                   screen: one.screen, rms_strain: c.rms_strain, max_strain: c.max_strain,
                   sim_ms: st.simMs[i], pinned: one.pinned, held: one.held, hands: one.hands, max_value: c.max_value,
                   high_value: c.high_value, imbalance: c.imbalance, max_stress: c.max_stress };
        });
      },
      setColorMode: app.colours.setMode,
      loadScene: scene.loadScene,
      // Extras for tests and the console.
      setScaleMode: function (mode, fullScale) {
        if (fullScale !== undefined) app.colours.setFullScale(fullScale);
        app.colours.setScaleMode(mode);
      },
      usePreset: function (name) { scene.usePreset(name); return true; },
      setParam: app.setParam,
      setSolver: app.setSolver,
      setCutTool: app.setCutTool,
      reset: scene.reset,
      cloth: function () { return panels.cloth(0); },
      // What the charts wrote at their last draw: [text, x, y, width, box x, y, w, h].
      chartTexts: function () { return app.charts.written(); },
      // RGBA at client coordinates, read right after a fresh draw.
      pixels: function (points) {
        app.render();
        const r = canvas.getBoundingClientRect();
        return renderer.readPixels(points.map(function (p) { return [p[0] - r.left, p[1] - r.top]; }));
      },
      info: function () {
        const st = app.status(), ui = app.ui, n = views.count(), c = n ? panels.cloth(0) : null;
        return {
          webgl: renderer.ok ? renderer.version : 0, lost: !!renderer.lost, restores: renderer.restores || 0,
          relayouts: st.relayouts,
          drawCalls: renderer.drawCalls || 0, paused: st.paused, mode: app.colours.mode(),
          scaleMode: app.colours.scaleMode(), scale: app.painter.scale(), fullScale: app.colours.fullScale(),
          autoFloor: clothReadouts.AUTO_FLOOR, frames: panels.frame(),
          preset: scene.preset(), params: scene.params(),
          asleep: !!(n && panels.asleep()), renders: app.painter.renders(),
          fps: st.fps, fpsAt: st.fpsAt, renderMs: app.painter.renderMs(),
          rects: views.rects().map(function (r) { return [r.x, r.y, r.w, r.h]; }),
          replay: { playing: panels.replayEnd() >= 0, end: panels.replayEnd(), ended: panels.replayEnded() },
          linkPending: app.files.linkPending(), panels: n,
          simMs: n ? st.simMs[0] : NaN, chartLatest: app.charts.latest(0),
          edges: c ? c.n_edges : 0, broken: c ? c.broken : 0,
          cutTool: app.bladeOn(),
          // The session runs in a Web Worker (sim/remote.js), and has run every frame asked of it.
          worker: !!panels.remote, idle: panels.remote ? panels.idle() : true,
          recorded: panels.recordingCount(), recordingFull: panels.recordingFull(),
          error: ui.errorText(), note: ui.noteText(), scene: scene.text(),
          canvas: [canvas.width, canvas.height], dpr: window.devicePixelRatio || 1,
        };
      },
    };
  }

  return { publish: publish };
})();
