// The core's public face in the page: window.clothCore.
//
// `clothTranscrypt.api` is the transpiled cloth/api.py (linked by build.py).
// Transcrypt exceptions are not JS Error instances (the message sits in
// e.__args__[0]), so every entry point turns them into a plain Error carrying
// the same one-line message the CLI prints.
'use strict';

window.clothCore = (function (api) {
  function message(e) {
    if (e instanceof Error) return e.message;
    if (e && e.__args__ && e.__args__.length > 0) return String(e.__args__[0]);
    return String(e);
  }

  function wrap(fn) {
    return function () {
      try {
        return fn.apply(null, arguments);
      } catch (e) {
        if (e instanceof Error) throw e;
        const err = new Error(message(e));
        err.cause = e;
        throw err;
      }
    };
  }

  const core = {
    // run(sceneJsonText, frames) -> JSON text, as the CLI prints it.
    run: wrap(function (text, frames) { return api.run(text, frames); }),
    // load(sceneJsonText) -> a live Cloth (typed arrays, frame(), measure(), grab()...).
    load: wrap(function (text) { return api.load(text); }),
    message: message,
    api: api,
  };
  if (typeof api.parse_scene === 'function') {
    core.parseScene = wrap(function (text) { return api.parse_scene(text); });
  }
  return core;
})(clothTranscrypt.api);
