// The scene in and out of the page (share.js: files, the clipboard, links) and what the person
// sees of it: the recording replayed, exported, copied as a link; a picture; a file or a link
// opened, with what the notes say of each.
import { clothCore } from '../sim/core.js';
import { clothOptions } from '../sim/options.js';
import { clothScenes } from '../sim/scenes.js';
import { clothShare } from '../sim/share.js';
import { clothReadouts } from './readouts.js';

export const clothFiles = (function () {
  const share = clothShare, scenes = clothScenes;

  // app: {panels (sim/panels.js), load(text, preset, view), loadNote() (what the last load
  // said of its scene), preset(), view(), comparing()
  // (compare mode runs), render(), drawable() (WebGL draws), paused(), setPaused(on)}; capture
  // (capture.js), ui.
  function create(app, capture, ui) {
    const panels = app.panels;
    let linkPending = false;     // a link is being opened (its scene inflates later)

    // What an import path says of the scene it loaded, with what the load said of the scene
    // itself (an older model, a heavy grid): one note, so that every way in says the same
    // (the file, the drop and the link's own words once replaced the older model's note).
    function say(text) { ui.note([text].concat(app.loadNote() ? [app.loadNote()] : []).join('; ')); }

    // Restart the recording from frame 0 at real speed.
    function replay() {
      panels.recording(function (text) {
        app.load(text, app.preset(), app.view());
        say(clothReadouts.replayNote(panels.replayEnd(), ''));
      });
    }

    function exportRecording() {
      const name = share.fileName(app.preset(), app.comparing(), panels.recordingComplete());
      panels.recording(function (text) { share.exportText(text, name, ui.note); });
    }

    // A Promise of the link that replays the recording.
    function link() { return new Promise(function (resolve) { panels.recording(resolve); }).then(share.linkFor); }

    function copyLink() { return share.copyLink(new Promise(function (resolve) { panels.recording(resolve); }), ui.note); }

    // A picture's or a video's name: the preset (or 'scene') and the frame it starts at.
    function mediaName() { return 'cloth-' + (app.preset() || 'scene') + '-f' + panels.frame(); }

    // Drawn now and saved in the same task (the WebGL canvas keeps its pixels until shown).
    function picture() {
      if (!app.drawable()) { ui.note('Picture: there is no WebGL drawing to save'); return null; }
      app.render();
      return capture.picture(mediaName());
    }

    function openFile(file) {
      share.readFile(file).then(function (text) {
        app.load(text, 'custom', null);
        say('Opened ' + file.name);
      }).catch(function (e) {
        ui.error('Scene not loaded: ' + clothCore.message(e) + ' (' + file.name + '; the previous scene keeps running)');
      });
    }

    // A link: the scene (a recording) in the fragment replaces the preset once decoded; it
    // replays and stops at its last frame. One that cannot be read leaves what runs running
    // (the URL's preset, on opening), and says which it is. A link pasted into the address bar
    // of the open page changes only the fragment: the same, over whatever the person had.
    function openLink() {
      const linked = share.sceneIn(window.location.hash);
      if (!linked) return;
      const wasPaused = app.paused();
      app.setPaused(true);
      linkPending = true;
      linked.then(function (text) {
        app.load(text, 'custom', null);
        say(clothReadouts.replayNote(panels.replayEnd(), 'the link'));
      }).catch(function (e) {
        const shown = clothOptions.own(scenes.PRESETS, app.preset())
          ? 'showing the ' + scenes.PRESETS[app.preset()].label + ' preset' : 'the scene shown runs on';
        ui.error('The link could not be opened: ' + clothCore.message(e) + '; ' + shown);
        app.setPaused(wasPaused);
      }).then(function () { linkPending = false; });
    }

    return { replay: replay, exportRecording: exportRecording, link: link, copyLink: copyLink, mediaName: mediaName,
             picture: picture, openFile: openFile, openLink: openLink,
             linkPending: function () { return linkPending; } };
  }

  return { create: create };
})();
