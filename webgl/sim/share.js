// Scenes in and out of the page without a server: a file saved by a Blob download, the
// clipboard, a file opened or dropped, and a link that carries the scene in its fragment.
//
// Link: #scene=<base64url of the deflate-raw compressed UTF-8 JSON> (CompressionStream; where
// a browser has none, #scene-json=<base64url of the JSON itself>). The fragment never leaves
// the browser, so a link works from file:// as from any host. MAX_LINK characters at most:
// a longer recording gets a note that offers the file instead.
//
// Bytes are decoded as the CLI decodes them (cloth/__main__.py): strict UTF-8, a leading
// byte-order mark skipped, and text that is not UTF-8 is refused with the CLI's message,
// naming the same offset.
import { clothCore } from './core.js';

export const clothShare = (function () {
  const MAX_LINK = 262144;
  // The most bytes a scene may have, however it comes in (cloth/scene.py MAX_SCENE_BYTES),
  // counted while it is read or inflated: a decompression bomb stops at the limit.
  const limit = clothCore.sceneLimit();
  const MAX_BYTES = limit.bytes;
  function tooLarge() {
    const e = new Error(limit.message);
    e.tooLarge = true;
    return e;
  }
  const ZIPPED = 'scene=', PLAIN = 'scene-json=';

  function toBase64Url(bytes) {
    let bin = '';
    const CHUNK = 0x8000;
    for (let i = 0; i < bytes.length; i += CHUNK) {
      bin += String.fromCharCode.apply(null, bytes.subarray(i, i + CHUNK));
    }
    return btoa(bin).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
  }

  function fromBase64Url(text) {
    if (!/^[A-Za-z0-9_-]*$/.test(text)) throw new Error('it holds characters that base64url has not');
    if (text.length % 4 === 1) throw new Error('it is cut short');
    let b64 = text.replace(/-/g, '+').replace(/_/g, '/');
    while (b64.length % 4) b64 += '=';
    const bin = atob(b64);
    const out = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; i++) out[i] = bin.charCodeAt(i);
    return out;
  }

  function pipe(bytes, stream) {
    const piped = new Blob([bytes]).stream().pipeThrough(stream);
    return new Response(piped).arrayBuffer().then(function (b) { return new Uint8Array(b); });
  }

  const canZip = typeof CompressionStream === 'function' && typeof DecompressionStream === 'function';

  // text -> Promise of the link (this page's address with the scene in its fragment).
  function linkFor(text) {
    const bytes = new TextEncoder().encode(text);
    const here = window.location.href.split('#')[0];
    const made = canZip ? pipe(bytes, new CompressionStream('deflate-raw')).then(function (z) {
      return here + '#' + ZIPPED + toBase64Url(z);
    }) : Promise.resolve(here + '#' + PLAIN + toBase64Url(bytes));
    return made;
  }

  // The fragment (location.hash) -> null when it carries no scene, else a Promise of the
  // scene's text; a malformed or truncated one rejects with an Error that says what is wrong.
  function sceneIn(hash) {
    const h = (hash || '').replace(/^#/, '');
    let zipped;
    if (h.indexOf(ZIPPED) === 0) zipped = true;
    else if (h.indexOf(PLAIN) === 0) zipped = false;
    else return null;
    const data = h.slice((zipped ? ZIPPED : PLAIN).length);
    return new Promise(function (resolve) {
      // base64url: 4 characters for 3 bytes; neither a scene nor its deflated form is longer
      if (data.length > Math.ceil(MAX_BYTES / 3) * 4) throw tooLarge();
      const bytes = fromBase64Url(data);
      if (!zipped) { resolve(bytes); return; }
      if (!canZip) throw new Error('this browser cannot decompress it (no DecompressionStream)');
      resolve(inflate(bytes));
    }).then(decode);
  }

  // Deflated bytes -> Promise of the inflated ones, read a chunk at a time and stopped (the
  // stream cancelled) as soon as they pass MAX_BYTES: never inflated in full first.
  function inflate(bytes) {
    // The deflated bytes go in a small slice per pull: a decompressor turns each chunk it is
    // given into all of its output at once, and deflate expands up to 1032:1, so a link fed
    // whole (a 2 MB fragment that inflates to 1.9 GB) would be inflated in full, 10 s of work,
    // before the first read could stop it. A slice of IN_SLICE bytes is at most about 1 MB out.
    const IN_SLICE = 1024;
    let fed = 0;
    const source = new ReadableStream({
      pull: function (c) {
        if (fed >= bytes.length) { c.close(); return; }
        c.enqueue(bytes.subarray(fed, Math.min(fed + IN_SLICE, bytes.length)));
        fed += IN_SLICE;
      },
    }, { highWaterMark: 0 });
    const reader = source.pipeThrough(new DecompressionStream('deflate-raw')).getReader();
    const parts = [];
    let total = 0;
    function next() {
      return reader.read().then(function (r) {
        if (r.done) {
          const out = new Uint8Array(total);
          let at = 0;
          parts.forEach(function (p) { out.set(p, at); at += p.length; });
          return out;
        }
        total += r.value.length;
        if (total > MAX_BYTES) {
          parts.length = 0;
          reader.cancel().catch(function () { /* already failed: nothing to stop */ });
          throw tooLarge();
        }
        parts.push(r.value);
        return next();
      });
    }
    return next().catch(function (e) {
      if (e && e.tooLarge) throw e;
      throw new Error('it does not decompress: it is damaged or cut short');
    });
  }

  // The offset of the first byte that is not UTF-8 (as Python's decoder reports it: the start
  // of the first ill-formed sequence), or -1.
  function badByte(b) {
    let i = 0;
    const n = b.length;
    while (i < n) {
      const c = b[i];
      if (c < 0x80) { i++; continue; }
      let need, lo = 0x80, hi = 0xBF;
      if (c >= 0xC2 && c <= 0xDF) need = 1;
      else if (c >= 0xE0 && c <= 0xEF) {
        need = 2;
        if (c === 0xE0) lo = 0xA0;
        if (c === 0xED) hi = 0x9F;
      } else if (c >= 0xF0 && c <= 0xF4) {
        need = 3;
        if (c === 0xF0) lo = 0x90;
        if (c === 0xF4) hi = 0x8F;
      } else return i;
      for (let j = 1; j <= need; j++) {
        if (i + j >= n) return i;
        const d = b[i + j];
        if (j === 1 ? (d < lo || d > hi) : (d < 0x80 || d > 0xBF)) return i;
      }
      i += need + 1;
    }
    return -1;
  }

  // Bytes -> text, as the CLI decodes a scene file; throws the CLI's message.
  function decode(bytes) {
    let b = bytes;
    if (b.length >= 3 && b[0] === 0xEF && b[1] === 0xBB && b[2] === 0xBF) b = b.subarray(3);
    const bad = badByte(b);
    if (bad >= 0) throw new Error('scene: not UTF-8 text (invalid byte at offset ' + bad + ')');
    return new TextDecoder('utf-8', { ignoreBOM: true }).decode(b);   // one BOM only, as Python's utf-8-sig
  }

  // Text typed or pasted (the Scene JSON box) -> the text a file of the same bytes decodes to:
  // one leading byte-order mark (U+FEFF) is not content, as Python's utf-8-sig and decode()
  // above have it.
  function fromText(text) {
    // its UTF-8 bytes: at least one a character, at most three (a surrogate pair: four for two)
    if (text.length > MAX_BYTES ||
        (text.length * 3 > MAX_BYTES && new TextEncoder().encode(text).length > MAX_BYTES)) throw tooLarge();
    return text.length > 0 && text.charCodeAt(0) === 0xFEFF ? text.slice(1) : text;
  }

  // A File (from a picker or a drop) -> Promise of its text, decoded as the CLI does.
  function readFile(file) {
    if (file.size > MAX_BYTES) return Promise.reject(tooLarge());   // not read at all
    return file.arrayBuffer().then(function (buf) { return decode(new Uint8Array(buf)); });
  }

  // Save text as a file: a Blob download, which works from file:// with no server.
  // Save `data` (a Blob, or JSON text) as a file `name` (the browser's download).
  function download(data, name) {
    const url = URL.createObjectURL(data instanceof Blob ? data : new Blob([data], { type: 'application/json' }));
    const a = document.createElement('a');
    a.href = url;
    a.download = name;
    document.body.appendChild(a);
    a.click();
    a.remove();
    setTimeout(function () { URL.revokeObjectURL(url); }, 0);
  }

  // Promise: resolves when the clipboard has the text, rejects where the browser refuses.
  function copy(text) {
    if (!navigator.clipboard || !navigator.clipboard.writeText) {
      return Promise.reject(new Error('this page has no clipboard access here'));
    }
    return navigator.clipboard.writeText(text);
  }

  // The same for text that is still being made (a Promise of it). WebKit lets a page write
  // the clipboard only within the task of the person's key press or click: a writeText after
  // a promise (CompressionStream's) is refused there. A ClipboardItem given the promise starts
  // the write in that task; where there is none, or the write is refused, the text is written
  // once it is made. Call it from the key or click handler itself.
  function copyLater(made) {
    if (window.ClipboardItem && navigator.clipboard && navigator.clipboard.write) {
      let item;
      try {
        item = new ClipboardItem({ 'text/plain': made.then(function (t) { return new Blob([t], { type: 'text/plain' }); }) });
      } catch (e) {
        item = null;
      }
      if (item) {
        return navigator.clipboard.write([item]).catch(function (err) {
          return made.then(function (t) { return copy(t); }, function () { throw err; });
        });
      }
    }
    return made.then(copy);
  }

  // A recording's file name: the preset (or 'scene'), compare mode, and the frames it covers.
  function fileName(preset, compared, frames) {
    return 'cloth-' + (preset || 'scene') + (compared ? '-compare' : '') + '-' + frames + 'f.json';
  }

  // Export: the recording saved as a file `name` and copied; note(text) says which.
  function exportText(text, name, note) {
    download(text, name);
    copy(text).then(function () {
      note('Recording saved as ' + name + ' and copied');
    }, function () {
      note('Recording saved as ' + name + ' (the browser kept the clipboard closed)');
    });
    return text;
  }

  // Copy link: the link that replays `text`, copied from the key or click handler itself
  // (copyLater: WebKit's clipboard needs the person's task). A link longer than MAX_LINK is
  // not copied: the note offers Export. `text` may be a Promise of it (a Worker's recording).
  // A Promise of the link.
  function copyLink(text, note) {
    const made = Promise.resolve(text).then(linkFor);
    const fits = made.then(function (url) {
      if (url.length > MAX_LINK) throw new Error('too long');
      return url;
    });
    return copyLater(fits).then(function () {
      return made.then(function (url) {
        note('Link copied (' + url.length + ' characters): it replays this recording');
        return url;
      });
    }, function () {
      return made.then(function (url) {
        if (url.length > MAX_LINK) {
          note('This recording makes a link of ' + url.length + ' characters, longer than the ' +
               MAX_LINK + ' a link may have: use Export to save it as a file');
        } else {
          window.prompt('Copy this link (the browser kept the clipboard closed):', url);
        }
        return url;
      });
    });
  }

  return { fileName: fileName, exportText: exportText, copyLink: copyLink, linkFor: linkFor, sceneIn: sceneIn,
           fromText: fromText, readFile: readFile, download: download };
})();
