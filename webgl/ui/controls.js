// What the panel's controls do (ui.js's handlers): each one the function of the module that
// owns it. The app adds those of its own loop (pause, step, the charts, the Cut tool).

export const clothControls = (function () {
  // m: {scene (scene.js), settings (settings.js), colours (colours.js), files (files.js),
  // capture (capture.js), ui}.
  function of(m) {
    return {
      reset: function () { m.scene.reset(); },
      preset: function (name) { m.scene.usePreset(name); },
      solver: function (name) { m.settings.setSolver(name); },
      material: function (name) { m.settings.setMaterial(name); },
      param: function (key, raw) { m.settings.setParam(key, raw); },
      mode: function (v) { m.colours.setMode(v || m.colours.otherMode()); },
      scaleMode: function (v) { m.colours.setScaleMode(v || m.colours.otherScale()); },
      fullScale: function (raw) { m.colours.setFullScale(raw); },
      loadJson: function (text) { m.scene.paste(text); },
      currentJson: function () { return JSON.stringify(m.scene.obj(), null, 1); },
      replay: function () { m.files.replay(); },
      exportFile: function () { m.files.exportRecording(); },
      copyLink: function () { m.files.copyLink(); },
      picture: function () { m.files.picture(); },
      video: function () { m.ui.setVideo(m.capture.toggleVideo(m.files.mediaName())); },
      openFile: function (file) { m.files.openFile(file); },
    };
  }

  return { of: of };
})();
