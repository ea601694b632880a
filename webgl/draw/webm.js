// A WebM's duration written into its header. MediaRecorder streams a WebM whose Segment has
// an unknown size and whose Info has no Duration (it did not know the length when it wrote
// them), so players show no length and cannot seek. withDuration() adds the Duration element
// to the Segment's Info (EBML: Matroska's element tree, ids and sizes as variable-length
// integers), nothing else changed.

export const clothWebm = (function () {
  const EBML = 0x1A45DFA3, SEGMENT = 0x18538067, INFO = 0x1549A966, SEEK_HEAD = 0x114D9B74;
  const DURATION = 0x4489, TIMECODE_SCALE = 0x2AD7B1;
  const DEFAULT_SCALE = 1e6;    // ns per tick when the Info says none (Matroska's default)

  // The variable-length integer at p: its length in bytes, its value (marker bit removed),
  // and whether it is the reserved "unknown" (every value bit set).
  function vint(b, p) {
    const first = b[p];
    let len = 1;
    while (len <= 8 && !(first & (0x80 >> (len - 1)))) len++;
    if (len > 8 || p + len > b.length) return null;
    let value = first & (0xFF >> len), ones = value === (0xFF >> len);
    for (let i = 1; i < len; i++) {
      value = value * 256 + b[p + i];
      if (b[p + i] !== 0xFF) ones = false;
    }
    return { len: len, value: value, unknown: ones };
  }

  // The element at p: {id, where its size field is and its length, start of data, size (-1:
  // unknown), end}.
  function element(b, p) {
    const id = vint(b, p);
    if (!id) return null;
    let idValue = 0;
    for (let i = 0; i < id.len; i++) idValue = idValue * 256 + b[p + i];
    const size = vint(b, p + id.len);
    if (!size) return null;
    const data = p + id.len + size.len;
    return { id: idValue, sizeAt: p + id.len, sizeLen: size.len, data: data, size: size.unknown ? -1 : size.value,
             end: size.unknown ? b.length : data + size.value };
  }

  function float64(v) {
    const out = new Uint8Array(8);
    new DataView(out.buffer).setFloat64(0, v);
    return out;
  }

  // bytes (a WebM) and its length in milliseconds -> the same WebM with the Duration in its
  // Info; the bytes unchanged (and why, in .why) where it already has one or is not a WebM
  // this can change safely.
  function withDuration(bytes, ms) {
    const b = bytes;
    const head = element(b, 0);
    if (!head || head.id !== EBML) return { bytes: b, why: 'not a WebM' };
    const seg = element(b, head.end);
    if (!seg || seg.id !== SEGMENT) return { bytes: b, why: 'no Segment' };
    for (let p = seg.data; p < seg.end;) {
      const e = element(b, p);
      if (!e || e.size < 0) break;
      // A SeekHead's offsets point past the Info: growing the Info would move what they name.
      if (e.id === SEEK_HEAD) return { bytes: b, why: 'a SeekHead' };
      if (e.id === INFO) return addDuration(b, seg, p, e, ms);
      p = e.end;
    }
    return { bytes: b, why: 'no Info' };
  }

  function addDuration(b, seg, at, info, ms) {
    let scale = DEFAULT_SCALE;
    for (let p = info.data; p < info.end;) {
      const e = element(b, p);
      if (!e || e.end > info.end) return { bytes: b, why: 'a malformed Info' };
      if (e.id === DURATION) return { bytes: b, why: 'it has a Duration' };
      if (e.id === TIMECODE_SCALE) {
        let v = 0;
        for (let i = e.data; i < e.end; i++) v = v * 256 + b[i];
        if (v > 0) scale = v;
      }
      p = e.end;
    }
    // Duration: id 0x4489, size 8 (one byte: 0x88), a float64 of ticks.
    const dur = new Uint8Array(11);
    dur[0] = 0x44; dur[1] = 0x89; dur[2] = 0x88;
    dur.set(float64(ms * 1e6 / scale), 3);
    // The Info again: its id, its new size as an 8-byte vint (any size fits), its children.
    const children = info.end - info.data, size = children + dur.length;
    const infoHead = new Uint8Array(4 + 8);
    infoHead.set([0x15, 0x49, 0xA9, 0x66, 0x01], 0);
    for (let i = 0, v = size; i < 7; i++, v = Math.floor(v / 256)) infoHead[11 - i] = v % 256;
    const grow = infoHead.length + size - (info.end - at);
    // A Segment of known size grows by as much (its size field rewritten in place).
    const out = new Uint8Array(b.length + grow);
    out.set(b.subarray(0, at), 0);
    out.set(infoHead, at);
    out.set(b.subarray(info.data, info.end), at + infoHead.length);
    out.set(dur, at + infoHead.length + children);
    out.set(b.subarray(info.end), at + infoHead.length + size);
    if (seg.size >= 0) {
      const p = seg.sizeAt, len = seg.sizeLen;
      let v = seg.size + grow;
      if (v >= Math.pow(2, 7 * len) - 1) return { bytes: b, why: 'a Segment size that cannot grow' };
      for (let i = len - 1; i >= 0; i--, v = Math.floor(v / 256)) out[p + i] = v % 256;
      out[p] |= 0x80 >> (len - 1);
    }
    return { bytes: out, why: '' };
  }

  return { withDuration: withDuration };
})();
