// The app: the loop and the wiring. The simulation's side is sim/ (panels.js, or remote.js: the
// session in a Worker); draw/ shows its snapshots, input/ turns pointers into its gestures, ui/
// holds the controls, the scene that runs, the readouts and the test seam (window.clothApp).
//
// Loop: the core advances a fixed dt per frame. With the session in a Worker (the default), the
// Worker keeps the simulation's own clock (sim/clock.js, sim/worker.js): it steps at wall-clock
// rate whatever the drawing's rate, and the page draws the latest state it posted, never
// waiting for it; the page only says whether it runs (not paused, not hidden). On the page's
// own thread (?worker=0) elapsed time goes into an accumulator, capped at MAX_GAP (a stall
// becomes a short pause, never a huge step); at most MAX_CATCHUP frames are due per animation
// frame, and no more run once FRAME_BUDGET_MS is spent: the rest is dropped (slow motion, and
// the readout says so), never owed, so input never waits for a burst of catch-up.
import { clothBlade } from './draw/blade.js';
import { clothCapture } from './draw/capture.js';
import { clothCharts } from './draw/charts.js';
import { clothColours } from './ui/colours.js';
import { clothCompare } from './ui/compare.js';
import { clothControls } from './ui/controls.js';
import { clothCore } from './sim/core.js';
import { clothFiles } from './ui/files.js';
import { clothGestures } from './input/gestures.js';
import { clothInput } from './input/input.js';
import { clothObstacles } from './draw/obstacles.js';
import { clothOptions } from './sim/options.js';
import { clothOverlays } from './draw/overlays.js';
import { clothPainter } from './draw/painter.js';
import { clothPanels } from './sim/panels.js';
import { clothReadouts } from './ui/readouts.js';
import { clothRemote } from './sim/remote.js';
import { clothRenderer } from './draw/renderer.js';
import { clothScene } from './ui/scene.js';
import { clothScenes } from './sim/scenes.js';
import { clothSeam } from './ui/seam.js';
import { clothSettings } from './ui/settings.js';
import { clothShare } from './sim/share.js';
import { clothStage } from './draw/stage.js';
import { clothUI } from './ui/ui.js';
import { clothViews } from './draw/views.js';

(function () {
  const MAX_GAP = 0.25;        // seconds of wall clock counted per animation frame at most
  const MAX_CATCHUP = 4;       // core frames per animation frame at most
  const FRAME_BUDGET_MS = 12;  // simulation time per animation frame at most (one frame always runs)
  const READOUT_MS = 250;      // readout refresh period

  const core = clothCore, scenes = clothScenes, stage = clothStage, share = clothShare;
  const canvas = document.getElementById('view');
  const options = clothOptions.parse(window.location.search, scenes.PRESETS);
  // The session in a Worker (the default); with ?worker=0, or where a Worker cannot start (and
  // the page says so), on this thread.
  let panels = options.worker ? clothRemote.start(arrived, stopped) : null;
  if (options.worker && !panels) options.notes.push('This browser could not start a Web Worker: the simulation runs on the page\'s own thread');
  panels = panels || clothPanels.create();

  let paused = false, acc = 0, last = -1, dirty = true, trail = false, bladeOn = false;
  let chartsOn = true, relayouts = 0;
  let wanted = 0, played = 0, speed = 1;   // wall-clock and simulated seconds since the last readout
  let fps = NaN, fpsAt = NaN, lastReadout = 0;

  const blade = clothBlade.create(document.getElementById('blade'));
  const obstacles = clothObstacles.create(document.getElementById('obstacles'));
  // Picture and Video: the stage as drawn, the cloth's canvas and the obstacles' over it.
  const capture = clothCapture.create([canvas, document.getElementById('obstacles')],
                                      function (blob, name) { share.download(blob, name); },
                                      function (text) { ui.note(text); });
  const controls = {};         // the controls' handlers (controls.js), filled once the modules exist
  const ui = clothUI.create(controls);
  const colours = clothColours.create(ui, function () { dirty = true; });
  const compareUI = clothCompare.create({
    change: function (list, note) { scene.setCompare(list, note); },
    note: function (text) { ui.note(text); },
    running: function (i, key) { return i < panels.count() ? panels.scene(i)[key] : null; },
  });
  const charts = clothCharts.create(document.getElementById('charts'));
  const renderer = clothRenderer.create(canvas, {
    webgl: options.webgl,
    onLost: function () {
      ui.error('The WebGL context was lost; waiting for the browser to restore it.', 'context');
      obstacles.draw([], [], -1);
    },
    onRestored: function () { ui.clearError('context'); views.restored(); dirty = true; },
    onError: function (msg) { ui.fatal(msg); },
  });
  if (!renderer.ok) ui.fatal(renderer.error);
  const painter = clothPainter.create(renderer, obstacles, capture);
  const overlays = clothOverlays.create(canvas, [document.getElementById('legend'),
    document.getElementById('hud'), document.getElementById('charts')], document.getElementById('overlays'));
  const views = clothViews.create(canvas, renderer, overlays.band, panels);
  const scene = clothScene.create({
    panels: panels, ui: ui, compareUI: compareUI, opened: opened, render: render, setPaused: setPaused,
    changed: function () { dirty = true; }, gestures: function () { return gestures; },
    settings: function () { return settings; },
  });
  const files = clothFiles.create({
    panels: panels, load: scene.load, loadNote: scene.loadNote, render: render, setPaused: setPaused, preset: scene.preset, view: scene.view,
    comparing: function () { return scene.compare().length > 0; }, drawable: function () { return renderer.ok; },
    paused: function () { return paused; },
  }, capture, ui);

  // The panels are new (a scene loaded): their views, charts and layout.
  function opened() {
    const snaps = [];
    for (let i = 0; i < panels.count(); i++) snaps.push(panels.snap(i));
    acc = 0; wanted = 0; played = 0; speed = 1;
    charts.reset(snaps.length);
    views.open(snaps, scene.view());
    compareUI.placeLabels(snaps.length > 1 ? views.rects() : []);
    dirty = true;
  }

  function setCutTool(on) { bladeOn = !!on; ui.setCutTool(bladeOn); canvas.classList.toggle('cutting', bladeOn); }

  function setCharts(on) { chartsOn = !!on; ui.setCharts(chartsOn); if (on) charts.draw(); relayout(); }

  // Runs up to n frames (panels.simulate); a replay stops at its last frame.
  function simulate(n, budgetMs) {
    const resting = panels.asleep();         // at rest: nothing stepped, nothing to draw again
    const done = panels.simulate(n, budgetMs);
    ran(done > 0 && !resting);
    return done;
  }

  // Frames ran (here, or in the Worker: arrived), `moved`: the cloth with them.
  function ran(moved) {
    if (panels.scriptRan()) { scene.scripted(); dirty = true; }
    if (moved) dirty = true;
    if (panels.atReplayEnd()) { scene.replayEnded(); setPaused(true); }
  }

  // The Worker posted its state: `done` more frames, or what gestures and settings did.
  function arrived(done) {
    if (done > 0 && views.count()) played += done * panels.read(0).dt;
    ran(true);
  }

  function stopped(msg) { setPaused(true); ui.error('Simulation stopped: ' + msg); }

  function render() {
    if (!views.count() || !renderer.ok) return;
    // The obstacles' layer never outlives the drawing it belongs to: while no cloth can be
    // drawn (a lost context), none is shown (a peg stayed over four presets after one).
    if (renderer.lost) { obstacles.draw([], [], -1); return; }
    overlays.fade(gestures.count() > 0, views.heldPoints);
    panels.refresh();
    painter.draw(views.list(), panels.reads(), colours, views.rects(), gestures.moving());
    dirty = false;
  }

  // Test seam: run `frames` frames now and draw them (with `undrawn`, leave the drawing to the
  // next animation frame: a script that steps thousands of times in one task would otherwise
  // queue a draw for each).
  function advance(frames, undrawn) {
    const n = Math.max(0, Math.floor(Number(frames) || 0));
    if (panels.remote) {
      // A Promise of the frame, once the Worker has run them all.
      return panels.run(n).then(function () { if (!undrawn) render(); return panels.frame(); });
    }
    if (n > 0) simulate(n);
    if (!undrawn) render();
    return panels.frame();
  }

  function setPaused(on) { paused = !!on; acc = 0; ui.setPaused(paused); running(); }

  // The Worker's clock runs while the page is neither paused nor hidden.
  function running() { if (panels.remote) panels.running(!paused && !document.hidden); }
  document.addEventListener('visibilitychange', running);

  const numbers = clothReadouts.create(ui, compareUI);
  const frameTimes = clothReadouts.frameClock();
  function readouts(now) {
    if (now - lastReadout < READOUT_MS || !views.count()) return;
    lastReadout = now;
    painter.timeNext();
    fps = frameTimes.rate();
    fpsAt = last;
    overlays.measure();
    if (panels.remote) speed = panels.rate();
    else if (wanted > 0) speed = played / wanted;
    wanted = 0; played = 0;
    panels.refresh();
    numbers.show({ reads: panels.reads(), simMs: panels.times(), rects: views.rects(), paused: paused, speed: speed,
                   away: views.away(),
                   renderMs: painter.renderMs(), fps: fps, scale: painter.scale(), scaleMode: colours.scaleMode(),
                   mode: colours.mode() }, panels.asleep());
    ui.setRecording({ frames: panels.frame(), actions: panels.recordingCount(), full: panels.recordingFull(),
                      complete: panels.recordingComplete(), replayEnd: panels.replayEnd() });
  }

  // Charts: a sample of each panel every SAMPLE_MS (charts.js) while the simulation runs, and
  // one for every frame stepped by hand.
  function panelRms(i) { return panels.read(i).rms_strain; }
  function sampleCharts(every) {
    if (charts.sample(performance.now(), panelRms, panels.simMs, every) && chartsOn) charts.draw();
  }

  function tick(nowMs) {
    window.requestAnimationFrame(tick);
    const now = nowMs / 1000;
    const gap = last < 0 ? 0 : Math.min(now - last, MAX_GAP);
    last = now;
    frameTimes.push(now);
    try {
      if (!paused && views.count()) {
        const dt = panels.read(0).dt;
        acc += gap;
        wanted += gap;
        if (!panels.remote) {
          const due = Math.min(Math.floor(acc / dt), MAX_CATCHUP);
          const done = due > 0 ? simulate(due, FRAME_BUDGET_MS) : 0;
          // What the budget or the catch-up cap left undone is dropped, not owed: a slow scene
          // runs in slow motion (the readout says so) and input is handled every frame.
          acc = done < due || Math.floor(acc / dt) > MAX_CATCHUP ? 0 : acc - done * dt;
          played += panels.asleep() ? gap : done * dt;
        }
        sampleCharts(false);
      }
      if (dirty || capture.recording()) render();
      if (trail) trail = blade.draw(performance.now());
    } catch (e) {
      setPaused(true);
      ui.error('Simulation stopped: ' + core.message(e));
    }
    readouts(nowMs);
  }

  // Pointers (input.js) become gestures (gestures.js) on the views below, and a gesture becomes
  // the panels' actions: applied at once in every panel and recorded at the current frame. A
  // person acting during a replay takes over.
  const gestures = clothGestures.create({
    locate: views.locate, toWorld: views.toWorld, toWorldWithin: views.toWorldWithin, pick: views.pick,
    positionOf: views.positionOf,
    obstacleAt: views.obstacleAt, centreOf: views.centreOf,
    // Held by someone else: another pointer, or the scene's script (a replay's script lets go
    // when a person takes over, so its vertices can be grabbed then).
    isHeld: function (k) { return panels.held(k) && (panels.replayEnd() < 0 || gestures.holds(k)); },
    bladeOn: function () { return bladeOn; },
    trail: function (x, y, start) {
      const r = canvas.getBoundingClientRect();
      blade.add(x - r.left, y - r.top, performance.now(), start);
      trail = true;
    },
  }, scene.act);
  clothInput.attach(canvas, gestures);

  // The panel's settings (settings.js): a `set` through the session, or a new grid.
  const settings = clothSettings.create({
    panels: panels, load: scene.load, acted: scene.acted, ui: ui, gestures: gestures, params: scene.params,
    compare: scene.compare, sceneObj: scene.obj, preset: scene.preset, pinEdits: scene.pinEdits,
    loadNote: scene.loadNote, followed: scene.followed, retuned: scene.retuned,
  });

  // The views laid out again (a resize, the charts shown or hidden): a held vertex stays under
  // its pointer, and the overlays' and the canvas's boxes are measured anew.
  function relayout() {
    relayouts++;
    views.layout();
    compareUI.placeLabels(views.count() > 1 ? views.rects() : []);
    gestures.reproject();
    overlays.measure();
    dirty = true;
  }

  if (renderer.ok) {
    stage.watch(canvas, function (w, h, devW, devH, observed) {
      renderer.resize(w, h, devW, devH);
      relayout();
      if (!observed) return;
      render();  // same task as the resize: no blank frame
      if (chartsOn) charts.draw();
    });
  }

  clothSeam.publish({
    panels: panels, views: views, scene: scene, canvas: canvas, renderer: renderer, charts: charts, ui: ui,
    painter: painter, colours: colours, files: files, bladeOn: function () { return bladeOn; },
    status: function () { return { paused: paused, relayouts: relayouts, fps: fps, fpsAt: fpsAt, simMs: panels.times().slice() }; },
    render: render, setPaused: setPaused, advance: advance, setParam: settings.setParam, setSolver: settings.setSolver,
    setCutTool: setCutTool,
  });

  Object.assign(controls, clothControls.of({ scene: scene, settings: settings, colours: colours, files: files,
                                            capture: capture, ui: ui }), {
    pause: function () { setPaused(!paused); },
    step: function () { setPaused(true); advance(1); sampleCharts(true); },
    charts: function (on) { setCharts(on); },
    cutTool: function (on) { setCutTool(on === undefined ? !bladeOn : on); },
  });

  colours.show();
  // On a small stage (a phone) the charts start hidden: with the readouts they would take most
  // of it. The Live charts box shows them.
  const box = canvas.getBoundingClientRect();
  if (box.width < 420 || box.height < 420) { chartsOn = false; ui.setCharts(false); }
  setPaused(false);
  try {
    scene.usePreset(options.preset);
  } catch (e) {
    ui.fatal('The default scene failed to load: ' + e.message);
  }
  if (options.paused) setPaused(true);
  if (options.notes.length) ui.note(options.notes.join('. '));
  files.openLink();
  window.addEventListener('hashchange', files.openLink);
  window.requestAnimationFrame(tick);
})();
