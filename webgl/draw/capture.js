// Export what is seen: a PNG of the stage at the canvas's device pixels (Picture) and a video
// of it as it plays (Video: MediaRecorder on a canvas's stream, in the best format the browser
// has). What is seen is two canvases, the cloth (WebGL) and the obstacles (2D) over it: both
// are drawn into one 2D canvas of the WebGL canvas's device size, for a picture once, for a
// video after every drawing while it records (nothing is copied otherwise). Files are saved
// through share.js; everything works offline from file://.
import { clothWebm } from './webm.js';

export const clothCapture = (function () {
  // The formats tried, best first: what MediaRecorder.isTypeSupported says yes to.
  const VIDEO_TYPES = ['video/webm;codecs=vp9', 'video/webm;codecs=vp8', 'video/webm',
                       'video/mp4;codecs=avc1', 'video/mp4'];
  const FPS = 60;

  // Why this browser cannot record the canvas ('' when it can), and the type it would use.
  function videoSupport() {
    const probe = document.createElement('canvas');
    if (!window.MediaRecorder) return { why: 'this browser has no MediaRecorder', type: '' };
    if (!probe.captureStream) return { why: 'this browser cannot stream a canvas (no captureStream)', type: '' };
    const test = MediaRecorder.isTypeSupported ? MediaRecorder.isTypeSupported.bind(MediaRecorder) : null;
    for (let i = 0; i < VIDEO_TYPES.length; i++) {
      if (!test || test(VIDEO_TYPES[i])) return { why: '', type: test ? VIDEO_TYPES[i] : '' };
    }
    return { why: 'this browser records no video format it can save (tried WebM and MP4)', type: '' };
  }

  // layers: [canvas, ...] bottom first (the first sets the size); save(blob, name); note(text).
  function create(layers, save, note) {
    const base = layers[0];
    let video = null;     // {recorder, chunks, canvas, ctx, type, started, name}

    // The layers drawn into ctx, at the base canvas's device size.
    function compose(ctx, w, h) {
      ctx.clearRect(0, 0, w, h);
      for (let i = 0; i < layers.length; i++) {
        if (layers[i].width > 0 && layers[i].height > 0) ctx.drawImage(layers[i], 0, 0, w, h);
      }
    }

    // Picture: call right after a drawing (the WebGL canvas keeps its pixels only until the
    // browser shows them). Saves name.png; a Promise of {name, width, height}.
    function picture(name) {
      const w = base.width, h = base.height;
      const c = document.createElement('canvas');
      c.width = w; c.height = h;
      compose(c.getContext('2d'), w, h);
      return new Promise(function (resolve, reject) {
        c.toBlob(function (blob) {
          if (!blob) { reject(new Error('the browser made no PNG')); return; }
          save(blob, name + '.png');
          note('Picture saved as ' + name + '.png (' + w + '×' + h + ' px)');
          resolve({ name: name + '.png', width: w, height: h });
        }, 'image/png');
      });
    }

    // Video: starts recording (returns true), or stops and saves it (returns false). Where the
    // browser cannot, says why and returns false.
    function toggleVideo(name) {
      if (video) { stop(); return false; }
      const support = videoSupport();
      if (support.why) { note('Video: ' + support.why + '; Picture saves a PNG'); return false; }
      const c = document.createElement('canvas');
      c.width = Math.max(2, base.width & ~1); c.height = Math.max(2, base.height & ~1);   // even: codecs want it
      const ctx = c.getContext('2d');
      compose(ctx, c.width, c.height);
      let recorder;
      try {
        recorder = new MediaRecorder(c.captureStream(FPS), support.type ? { mimeType: support.type } : {});
      } catch (e) {
        note('Video: this browser refused to record the canvas (' + (e && e.message ? e.message : e) + ')');
        return false;
      }
      const type = recorder.mimeType || support.type || 'video/webm';
      video = { recorder: recorder, chunks: [], canvas: c, ctx: ctx, type: type, started: performance.now(),
                name: name + (type.indexOf('mp4') >= 0 ? '.mp4' : '.webm') };
      const v = video;
      recorder.ondataavailable = function (e) { if (e.data && e.data.size > 0) v.chunks.push(e.data); };
      recorder.onerror = function (e) {
        note('Video: the browser\'s recorder failed (' + (e && e.error && e.error.message ? e.error.message : 'no reason given') + ')');
      };
      recorder.onstop = function () {
        const blob = new Blob(v.chunks, { type: v.type.split(';')[0] });
        // A recorder that takes a format it cannot encode (WebKitGTK without GStreamer's
        // encoders says yes to MP4) gives no data: an empty file would be a broken video.
        if (blob.size === 0) {
          note('Video: the browser recorded nothing (its recorder gave no data for ' + v.type.split(';')[0] +
               '); nothing saved; Picture saves a PNG');
          return;
        }
        const ms = performance.now() - v.started;
        const said = function (saved, why) {
          save(saved, v.name);
          note('Video saved as ' + v.name + ' (' + (ms / 1000).toFixed(1) + ' s, ' + v.type.split(';')[0] + ', ' +
               Math.round(saved.size / 1024) + ' kB' + (why ? '; no duration in its header: ' + why : '') + ')');
        };
        // A WebM gets its duration written into its header: without it players cannot seek.
        if (v.type.indexOf('webm') < 0) { said(blob, ''); return; }
        blob.arrayBuffer().then(function (buf) {
          const done = clothWebm.withDuration(new Uint8Array(buf), ms);
          said(done.why ? blob : new Blob([done.bytes], { type: blob.type }), done.why);
        }).catch(function (e) { said(blob, String(e && e.message || e)); });
      };
      recorder.start(250);
      note('Recording video (' + type.split(';')[0] + '): Stop video saves it');
      return true;
    }

    function stop() {
      const v = video;
      video = null;
      if (v.recorder.state !== 'inactive') v.recorder.stop();
    }

    // After every drawing: the video's frame (nothing when not recording). While it records,
    // the app draws every animation frame, paused or not (recording()): a paused stretch is
    // the paused picture for as long as it lasted, not one frame.
    function drawn() {
      if (video) compose(video.ctx, video.canvas.width, video.canvas.height);
    }

    return { picture: picture, toggleVideo: toggleVideo, drawn: drawn,
             recording: function () { return !!video; } };
  }

  return { create: create, videoSupport: videoSupport };
})();
