// Raw WebGL renderer: every edge in one draw call, pins as markers.
//
// Data layout (one Float32Array, six floats an edge):
//   [ax, ay, bx, by, va, vb] * n_edges      world metres; va/vb = colour value at each end
// A quad (corner = (end 0|1, side -1|+1)) is stretched over each edge in the vertex shader
// (shaders/edge-quad.glsl), in device pixels. WebGL 2 sends the array as a texture, three
// RG32F texels an edge, and draws six vertices an edge that fetch it by gl_VertexID
// (shaders/edge-fetch.vert); WebGL 1 sends it as an instanced attribute buffer, one instance an
// edge over a static 4-vertex strip (shaders/edge.vert). Why not instances everywhere: a
// software rasteriser pays per instance (SwiftShader, Chromium's WebGL without a GPU: 70 ms of
// CPU a frame for a 40x30 curtain's 4,592 edges, 9 ms without that draw). A scene with more edges
// than a texture holds takes WebGL 1's way.
// Per frame the arrays are refilled in place and sent with texSubImage2D or bufferSubData;
// they are reallocated only when a scene with more edges or vertices arrives.
//
// What it draws is a snapshot (clothCore.snapshot): positions, the edges' ends, a value per
// edge and per vertex, and the markers' flags; it never reads the cloth itself.
//
// Panels: one canvas, one or more panels (compare mode runs 2 to 4 cloths side by side),
// each with its own arrays, its own rectangle of the canvas and its own world -> pixel
// view. r.begin() clears the canvas; each panel then draws into its rectangle.
//
// Dense grids: where a cell is under FILL_CELL_CSS pixels, edges thinner than a pixel and
// closer than two alias with the pixel grid into bands that are not in the field (a 150x150
// curtain showed a stripe every 13 rows over a smooth strain). There the cells are filled
// instead, one indexed draw of two triangles a cell, each vertex coloured by the largest value
// of its edges (strain) or its node stress, interpolated across the cell; and the cloth's
// outline (every structural edge with an intact cell on at most one side: the border, a cut's
// lips, a strand) drawn over them as edges, so that a cloth folded or pulled narrower than a
// pixel, whose cells cover no pixel's centre, still shows (the Chain at 60x60 folded into a
// strip 6.6 mm wide, under a pixel, and was not drawn at all).
//
// Colour (shaders/colour.glsl, t = clamp(value / scale, 0, 1)):
//   strain: value = |diff| of the edge at both ends, red = base + (1 - base) * t,
//           so brightness grows linearly with |diff| and an unstrained edge stays visible;
//   stress: value = node Q at each end, colour = mix(blue, red, t): the gradient
//           between the two nodes' colours comes from interpolating Q along the edge.

export const clothRenderer = (function () {
  const STRAIN_BASE = 0.3;          // red level of an unstrained edge
  const BACKGROUND = [0.075, 0.082, 0.098];
  const EDGE_HALF_WIDTH_CSS = 0.75; // half the edge width, CSS pixels (dense grids: thinner)
  const DENSE_CELL_CSS = 8;         // below this grid cell size (CSS px) edges thin out
  const FILL_CELL_CSS = 4;          // below this one the cells are filled instead (see above)
  const PIN_RADIUS_CSS = 4.5;
  const HELD_RADIUS_CSS = 8;

  // The GLSL lives in webgl/shaders/*.vert|frag; build.py inlines each file as a
  // <script type="x-shader/..." id="shader-NAME"> element, read here by name.
  function shader(name) {
    const el = document.getElementById('shader-' + name);
    if (!el) throw new Error('shader ' + name + ' is missing from the page (rebuild with build.py)');
    return el.textContent;
  }

  function numbered(src) {
    return src.split('\n').map(function (l, i) { return (i + 1) + ': ' + l; }).join('\n');
  }

  function compile(gl, type, src, name) {
    const sh = gl.createShader(type);
    gl.shaderSource(sh, src);
    gl.compileShader(sh);
    if (!gl.getShaderParameter(sh, gl.COMPILE_STATUS) && !gl.isContextLost()) {
      const log = gl.getShaderInfoLog(sh);
      gl.deleteShader(sh);
      throw new Error(name + ' shader failed to compile:\n' + log + '\n' + numbered(src));
    }
    return sh;
  }

  function program(gl, vs, fs, attribs, name) {
    const p = gl.createProgram();
    gl.attachShader(p, compile(gl, gl.VERTEX_SHADER, vs, name + ' vertex'));
    gl.attachShader(p, compile(gl, gl.FRAGMENT_SHADER, fs, name + ' fragment'));
    attribs.forEach(function (a, i) { gl.bindAttribLocation(p, i, a); });
    gl.linkProgram(p);
    if (!gl.getProgramParameter(p, gl.LINK_STATUS) && !gl.isContextLost()) {
      throw new Error(name + ' program failed to link: ' + gl.getProgramInfoLog(p));
    }
    const u = {};
    const n = gl.getProgramParameter(p, gl.ACTIVE_UNIFORMS) || 0;
    for (let i = 0; i < n; i++) {
      const info = gl.getActiveUniform(p, i);
      u[info.name] = gl.getUniformLocation(p, info.name);
    }
    return { prog: p, u: u };
  }

  // create(canvas, {webgl: 'auto'|'1'|'0', onLost, onRestored}) -> renderer.
  // renderer.ok is false (and renderer.error says why) when there is no usable WebGL.
  function create(canvas, opts) {
    opts = opts || {};
    const attrs = { antialias: false, alpha: false, depth: false, stencil: false,
                    premultipliedAlpha: true, preserveDrawingBuffer: false };
    let gl = null, version = 0;
    if (opts.webgl !== '0') {
      if (opts.webgl !== '1') {
        gl = canvas.getContext('webgl2', attrs);
        if (gl) version = 2;
      }
      if (!gl) {
        gl = canvas.getContext('webgl', attrs) || canvas.getContext('experimental-webgl', attrs);
        if (gl) version = 1;
      }
    }
    const r = {
      ok: false, error: '', version: version, gl: gl, lost: false,
      cssWidth: 1, cssHeight: 1, dpr: 1, drawCalls: 0, restores: 0,
    };
    if (!gl && opts.webgl === '0') {
      r.error = 'Drawing is off: the URL asks for no WebGL (?webgl=0). Remove it from the ' +
        'address to see the cloth.';
      return r;
    }
    if (!gl) {
      r.error = 'This browser cannot create a WebGL context (neither WebGL 2 nor WebGL 1). ' +
        'Enable hardware acceleration or WebGL in the browser settings, or try another browser.';
      return r;
    }

    let inst = null, edgeProg = null, markProg = null, cellProg = null;
    let fetchProg = null;     // WebGL 2's edges (no instances), null on WebGL 1
    let mostPerRow = 0;       // edges a row of its texture holds at most, and rows at most
    let mostRows = 0;
    let bigIndices = false;   // 32-bit element indices (WebGL 2, or WebGL 1's extension)
    let cornerBuf = null, markCornerBuf = null;
    let gen = 0;          // bumped when the GL objects are made again (a restored context)

    function initGL() {
      gl.clearColor(BACKGROUND[0], BACKGROUND[1], BACKGROUND[2], 1);
      if (version === 2) {
        inst = {
          divisor: function (i, d) { gl.vertexAttribDivisor(i, d); },
          draw: function (mode, first, count, n) { gl.drawArraysInstanced(mode, first, count, n); },
        };
      } else {
        const ext = gl.getExtension('ANGLE_instanced_arrays');
        if (!ext) throw new Error('WebGL 1 without ANGLE_instanced_arrays is not supported');
        inst = {
          divisor: function (i, d) { ext.vertexAttribDivisorANGLE(i, d); },
          draw: function (mode, first, count, n) { ext.drawArraysInstancedANGLE(mode, first, count, n); },
        };
      }
      const colour = shader('colour.glsl'), quad = shader('edge-quad.glsl');
      edgeProg = program(gl, quad + shader('edge.vert'), colour + shader('edge.frag'), ['a_corner', 'a_pa', 'a_pb', 'a_val'], 'edge');
      if (version === 2) {
        // '#version' must come first (the inlined script's text starts with a newline).
        fetchProg = program(gl, shader('es3.vert').trimStart() + quad + shader('edge-fetch.vert'),
                            shader('es3.frag').trimStart() + colour + shader('edge.frag'), [], 'edge (fetched)');
        mostRows = gl.getParameter(gl.MAX_TEXTURE_SIZE);
        mostPerRow = Math.floor(mostRows / 3);
      }
      cellProg = program(gl, shader('cell.vert'), colour + shader('cell.frag'), ['a_pos', 'a_val'], 'cell');
      bigIndices = version === 2 || !!gl.getExtension('OES_element_index_uint');
      markProg = program(gl, shader('mark.vert'), shader('mark.frag'), ['a_corner', 'a_center', 'a_kind'], 'marker');
      cornerBuf = gl.createBuffer();
      gl.bindBuffer(gl.ARRAY_BUFFER, cornerBuf);
      gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([0, -1, 0, 1, 1, -1, 1, 1]), gl.STATIC_DRAW);
      markCornerBuf = gl.createBuffer();
      gl.bindBuffer(gl.ARRAY_BUFFER, markCornerBuf);
      gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([-1, -1, -1, 1, 1, -1, 1, 1]), gl.STATIC_DRAW);
      gl.disable(gl.DEPTH_TEST);
      gl.enable(gl.BLEND);
      gl.blendFunc(gl.ONE, gl.ONE_MINUS_SRC_ALPHA);
      gen++;
    }

    try {
      initGL();
    } catch (e) {
      r.error = 'WebGL setup failed: ' + e.message;
      return r;
    }
    r.ok = true;

    canvas.addEventListener('webglcontextlost', function (e) {
      e.preventDefault();  // without this the browser never restores the context
      r.lost = true;
      if (opts.onLost) opts.onLost();
    });
    canvas.addEventListener('webglcontextrestored', function () {
      try {
        initGL();
        r.lost = false;
        r.restores += 1;
        if (opts.onRestored) opts.onRestored();
      } catch (e) {
        r.error = 'WebGL could not be restored: ' + e.message;
        if (opts.onError) opts.onError(r.error);
      }
    });

    // Match the drawing buffer to the canvas's CSS size times devicePixelRatio
    // (pixel-exact when the browser reports device-pixel sizes).
    r.resize = function (cssW, cssH, devW, devH) {
      r.dpr = window.devicePixelRatio || 1;
      r.cssWidth = Math.max(cssW, 1);
      r.cssHeight = Math.max(cssH, 1);
      const w = Math.max(1, devW || Math.round(r.cssWidth * r.dpr));
      const h = Math.max(1, devH || Math.round(r.cssHeight * r.dpr));
      if (canvas.width !== w) canvas.width = w;
      if (canvas.height !== h) canvas.height = h;
      panels.forEach(function (p) { p.fit(); });
    };

    // Wait until the GPU has drawn everything issued (the render readout's sample: without
    // it a timer sees only the issuing of the draw, and the drawing itself is paid unseen at
    // the next frame's swap).
    r.finish = function () {
      if (!r.lost && !gl.isContextLost()) gl.finish();
    };

    // Clear the whole canvas: a frame starts here, then each panel draws into its rectangle.
    r.begin = function () {
      r.drawCalls = 0;
      if (r.lost || gl.isContextLost()) return;
      gl.viewport(0, 0, canvas.width, canvas.height);
      gl.clear(gl.COLOR_BUFFER_BIT);
    };

    const panels = [];
    // The drawing of panel i (compare mode draws several cloths side by side in one canvas,
    // each in its own rectangle with its own view); made on first use.
    r.panel = function (i) {
      while (panels.length <= i) panels.push(makePanel());
      return panels[i];
    };

    function makePanel() {
      const p = {};
      let edgeBuf = null, markBuf = null, cellBuf = null, cellIdxBuf = null, bufGen = -1;
      // The cells: [x, y, value] per vertex, two triangles per intact cell (indices), and
      // the scratch that finds them; made per scene, the indices again when edges go.
      let cellData = new Float32Array(0), cellSum = new Float32Array(0);
      let cellIdx = new Uint32Array(0), right = new Uint8Array(0), down = new Uint8Array(0);
      let far = new Uint8Array(0), nFar = 0;
      // The outline's edges (indices into the snapshot's), found with the cells: each
      // structural edge's intact cells (rightCells, downCells: 0, 1 or 2) and index.
      let rightCells = new Uint8Array(0), downCells = new Uint8Array(0);
      let rightEdge = new Int32Array(0), downEdge = new Int32Array(0), outline = new Int32Array(0), nOutline = 0;
      let cellView = cellData, nCellIdx = 0, cellsFor = -1, cols = 0, rows = 0;
      let edgeData = new Float32Array(0), markData = new Float32Array(0);
      let edgeView = edgeData;  // edgeData's first 6 * n_edges floats, made once per scene
      let edgeCap = 0, markCap = 0;
      // WebGL 2's edge texture: edges a row (0: the edges go by instances, WebGL 1's way) and rows.
      let edgeTex = null, perRow = 0, texRows = 0;
      let view = { x0: 0, x1: 1, y0: -1, y1: 0 };
      let spacing = 1;  // the grid's rest length, metres: sets the edge width
      // The panel's rectangle in the canvas (CSS px; null: the whole canvas), and
      // world -> canvas CSS pixels: cssX = ox + s * x, cssY = oy - s * y.
      let rect = null, fitBox = null;
      let s = 1, ox = 0, oy = 0;

      function buffers() {
        if (bufGen === gen) return;
        edgeBuf = gl.createBuffer();
        gl.bindBuffer(gl.ARRAY_BUFFER, edgeBuf);
        gl.bufferData(gl.ARRAY_BUFFER, edgeBytes(), gl.DYNAMIC_DRAW);
        markBuf = gl.createBuffer();
        gl.bindBuffer(gl.ARRAY_BUFFER, markBuf);
        gl.bufferData(gl.ARRAY_BUFFER, markData.byteLength || 4, gl.DYNAMIC_DRAW);
        cellBuf = gl.createBuffer();
        gl.bindBuffer(gl.ARRAY_BUFFER, cellBuf);
        gl.bufferData(gl.ARRAY_BUFFER, cellData.byteLength || 4, gl.DYNAMIC_DRAW);
        cellIdxBuf = gl.createBuffer();
        edgeTex = null;
        if (perRow > 0) makeEdgeTexture();
        cellsFor = -1;
        bufGen = gen;
      }

      // The instanced edges' buffer: the array's size, or a stub while the texture holds them.
      function edgeBytes() { return perRow > 0 ? 4 : edgeData.byteLength || 4; }

      function makeEdgeTexture() {
        if (edgeTex) gl.deleteTexture(edgeTex);
        edgeTex = gl.createTexture();
        gl.bindTexture(gl.TEXTURE_2D, edgeTex);
        // Fetched texel by texel: no filtering (a float texture with filtering is incomplete).
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
        gl.texImage2D(gl.TEXTURE_2D, 0, gl.RG32F, 3 * perRow, texRows, 0, gl.RG, gl.FLOAT, null);
      }

      function box() {
        return rect || { x: 0, y: 0, w: r.cssWidth, h: r.cssHeight };
      }

      // Fit the view box inside the panel's rectangle (or the part of it set by setFit) less
      // a small inset, keeping aspect.
      p.fit = function () {
        const b = fitBox || box();
        const bw = Math.max(view.x1 - view.x0, 1e-9), bh = Math.max(view.y1 - view.y0, 1e-9);
        const inset = Math.min(16, b.w / 8, b.h / 8);
        s = Math.max(Math.min((b.w - 2 * inset) / bw, (b.h - 2 * inset) / bh), 1e-9);
        ox = b.x + b.w / 2 - s * (view.x0 + view.x1) / 2;
        oy = b.y + b.h / 2 + s * (view.y0 + view.y1) / 2;
      };

      // Size the arrays (and GPU buffers) for a scene; only grows.
      p.setScene = function (snap) {
        buffers();
        const ne = snap.n_edges, nv = snap.n_verts;
        if (ne > edgeCap) {
          if (fetchProg && ne <= mostPerRow * mostRows) {
            // Whole rows of the texture: the array is sent a row at a time.
            perRow = Math.min(ne, mostPerRow);
            texRows = Math.ceil(ne / perRow);
            edgeCap = perRow * texRows;
            makeEdgeTexture();
          } else {
            perRow = 0;
            edgeCap = ne;
          }
          edgeData = new Float32Array(6 * edgeCap);
          gl.bindBuffer(gl.ARRAY_BUFFER, edgeBuf);
          gl.bufferData(gl.ARRAY_BUFFER, edgeBytes(), gl.DYNAMIC_DRAW);
        }
        if (nv > markCap) {
          markCap = nv;
          markData = new Float32Array(3 * nv);
          gl.bindBuffer(gl.ARRAY_BUFFER, markBuf);
          gl.bufferData(gl.ARRAY_BUFFER, markData.byteLength, gl.DYNAMIC_DRAW);
        }
        edgeView = edgeData.subarray(0, 6 * ne);
        spacing = snap.spacing > 0 ? snap.spacing : 1;
        if (nv > cellSum.length) {
          cellData = new Float32Array(3 * nv);
          cellSum = new Float32Array(nv);
          right = new Uint8Array(nv);
          down = new Uint8Array(nv);
          far = new Uint8Array(nv);
          rightCells = new Uint8Array(nv);
          downCells = new Uint8Array(nv);
          rightEdge = new Int32Array(nv);
          downEdge = new Int32Array(nv);
          outline = new Int32Array(2 * nv);
          gl.bindBuffer(gl.ARRAY_BUFFER, cellBuf);
          gl.bufferData(gl.ARRAY_BUFFER, cellData.byteLength, gl.DYNAMIC_DRAW);
        }
        const cells = Math.max(snap.cols - 1, 0) * Math.max(snap.rows - 1, 0);
        if (6 * cells > cellIdx.length) cellIdx = new Uint32Array(6 * cells);
        cellView = cellData.subarray(0, 3 * nv);
        cols = snap.cols; rows = snap.rows;
        cellsFor = -1;
      };

      // A program that colours by value (edges, cells) in use, with the panel's view (world
      // metres -> its device pixels) and the colour scale set.
      function useColoured(prog, px, offX, offY, vw, vh, stressMode, scale) {
        gl.useProgram(prog.prog);
        const u = prog.u;
        gl.uniform2f(u.u_scale, s * px, -s * px);
        gl.uniform2f(u.u_offset, offX, offY);
        gl.uniform2f(u.u_viewport, vw, vh);
        gl.uniform1f(u.u_mode, stressMode ? 1 : 0);
        gl.uniform1f(u.u_invScale, scale > 1e-12 ? 1 / scale : 0);
        gl.uniform1f(u.u_base, STRAIN_BASE);
      }

      // The intact cells' triangles (its four structural edges all there), for the edges
      // the snapshot has: again only when their number changes (a tear or a cut), and every
      // frame while a vertex is far outside the panel (vertexValues), without the cells at it.
      function findCells(snap) {
        if (cellsFor === snap.n_edges && nFar === 0) return;
        const nv = snap.n_verts, ea = snap.edge_a, eb = snap.edge_b;
        for (let k = 0; k < nv; k++) { right[k] = 0; down[k] = 0; rightCells[k] = 0; downCells[k] = 0; }
        for (let e = 0; e < snap.n_edges; e++) {
          const a = Math.min(ea[e], eb[e]), b = Math.max(ea[e], eb[e]);
          if (b === a + 1) { right[a] = 1; rightEdge[a] = e; }
          else if (b === a + cols) { down[a] = 1; downEdge[a] = e; }
        }
        nCellIdx = 0;
        for (let r = 0; r + 1 < rows; r++) {
          for (let c = 0; c + 1 < cols; c++) {
            const k = r * cols + c;
            if (!right[k] || !down[k] || !right[k + cols] || !down[k + 1]) continue;
            rightCells[k]++; rightCells[k + cols]++; downCells[k]++; downCells[k + 1]++;
            if (nFar > 0 && (far[k] || far[k + 1] || far[k + cols] || far[k + cols + 1])) continue;
            cellIdx[nCellIdx++] = k; cellIdx[nCellIdx++] = k + 1; cellIdx[nCellIdx++] = k + cols;
            cellIdx[nCellIdx++] = k + 1; cellIdx[nCellIdx++] = k + cols + 1; cellIdx[nCellIdx++] = k + cols;
          }
        }
        nOutline = 0;
        for (let k = 0; k < nv; k++) {
          if (right[k] && rightCells[k] < 2) outline[nOutline++] = rightEdge[k];
          if (down[k] && downCells[k] < 2) outline[nOutline++] = downEdge[k];
        }
        gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, cellIdxBuf);
        gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, cellIdx.subarray(0, nCellIdx), gl.DYNAMIC_DRAW);
        cellsFor = nFar > 0 ? -1 : snap.n_edges;
      }

      // Each vertex's colour value into cellData (with its position): the largest of its
      // structural edges' values (strain: the brightest edge there, as the edges would show
      // it; a curtain's rows are slack and its columns carry the weight, and a mean would
      // halve it), or its node stress. And which vertices are farther than the panel's own
      // size outside it: a filled cell is a few pixels, so a cell at such a vertex is either
      // off the panel altogether or torn across it by a cloth that blew up (XPBD on Two
      // corners at 200x200), whose 40,000 cells, each as large as the panel, took a software
      // rasteriser 80 s a frame. findCells leaves those cells out.
      function vertexValues(snap, stressMode) {
        const nv = snap.n_verts, pos = snap.pos, cd = cellData;
        const b = box(), x0 = b.x - b.w, x1 = b.x + 2 * b.w, y0 = b.y - b.h, y1 = b.y + 2 * b.h;
        nFar = 0;
        for (let k = 0; k < nv; k++) {
          const cx = ox + s * pos[2 * k], cy = oy - s * pos[2 * k + 1];
          // (a NaN fails every comparison: far)
          const inside = cx >= x0 && cx <= x1 && cy >= y0 && cy <= y1;
          far[k] = inside ? 0 : 1;
          if (!inside) nFar++;
        }
        if (stressMode) {
          const q = snap.vertex_value;
          for (let k = 0; k < nv; k++) cellSum[k] = q[k];
        } else {
          for (let k = 0; k < nv; k++) cellSum[k] = 0;
          const ea = snap.edge_a, eb = snap.edge_b, v = snap.edge_value;
          for (let e = 0; e < snap.n_edges; e++) {
            const x = Math.abs(v[e]);
            if (x > cellSum[ea[e]]) cellSum[ea[e]] = x;
            if (x > cellSum[eb[e]]) cellSum[eb[e]] = x;
          }
        }
        for (let k = 0, o = 0; k < nv; k++, o += 3) {
          cd[o] = pos[2 * k]; cd[o + 1] = pos[2 * k + 1]; cd[o + 2] = cellSum[k];
        }
      }

      p.setView = function (b) { view = { x0: b.x0, x1: b.x1, y0: b.y0, y1: b.y1 }; p.fit(); };
      // The panel's rectangle, CSS px inside the canvas (null: all of it).
      p.setRect = function (x, y, w, h) {
        rect = w === undefined ? null : { x: x, y: y, w: Math.max(w, 1), h: Math.max(h, 1) };
        p.fit();
      };
      // Where in the rectangle the view is fitted (CSS px inside the canvas; null: all of
      // it): the cloth is drawn over the whole rectangle, fitted clear of the overlays.
      p.setFit = function (x, y, w, h) {
        fitBox = w === undefined ? null : { x: x, y: y, w: Math.max(w, 1), h: Math.max(h, 1) };
        p.fit();
      };
      // The panel's rectangle, CSS px inside the canvas.
      p.box = function () { return box(); };
      p.contains = function (cx, cy) {
        const b = box();
        return cx >= b.x && cx < b.x + b.w && cy >= b.y && cy < b.y + b.h;
      };
      p.pixelsPerMetre = function () { return s; };
      // CSS pixels relative to the canvas's top-left corner.
      p.toCanvas = function (x, y) { return [ox + s * x, oy - s * y]; };
      p.toWorld = function (cx, cy) { return [(cx - ox) / s, (oy - cy) / s]; };
      // The same, one coordinate at a time (no array: a per-frame overlay's drawing).
      p.canvasX = function (x) { return ox + s * x; };
      p.canvasY = function (y) { return oy - s * y; };

      // Half the edge width in device pixels. At least one device pixel on ordinary
      // grids, so every edge has a fully covered core pixel; on dense grids edges thin
      // out (down to half a pixel, antialiased) so the cells stay open.
      function halfWidth(px) {
        const cell = spacing * s;
        if (cell >= DENSE_CELL_CSS) return Math.max(EDGE_HALF_WIDTH_CSS * px, 1.0);
        return Math.max(Math.max(0.3, 0.1 * cell) * px, 0.5);
      }

      // The hot path: refill the arrays in place from a snapshot (clothCore.snapshot: all
      // the renderer reads of a cloth), upload, two draw calls into the panel's rectangle
      // (after r.begin()).
      p.draw = function (snap, mode, scale) {
        if (r.lost || gl.isContextLost()) return;
        buffers();
        const ne = Math.min(snap.n_edges, edgeCap), nv = Math.min(snap.n_verts, markCap);
        const pos = snap.pos, ea = snap.edge_a, eb = snap.edge_b;
        const ed = edgeData;
        const stressMode = mode === 'stress';
        const fill = bigIndices && cols > 1 && rows > 1 && spacing * s < FILL_CELL_CSS;
        let nd = ne;                  // the edges drawn as edges: all, or the outline's
        if (fill) {
          vertexValues(snap, stressMode);
          findCells(snap);
          nd = nOutline;
          const v = stressMode ? snap.vertex_value : snap.edge_value;
          for (let i = 0, o = 0; i < nOutline; i++, o += 6) {
            const e = outline[i], a = ea[e], b = eb[e];
            ed[o] = pos[2 * a]; ed[o + 1] = pos[2 * a + 1];
            ed[o + 2] = pos[2 * b]; ed[o + 3] = pos[2 * b + 1];
            ed[o + 4] = stressMode ? v[a] : Math.abs(v[e]); ed[o + 5] = stressMode ? v[b] : Math.abs(v[e]);
          }
        } else if (stressMode) {
          const q = snap.vertex_value;
          for (let e = 0, o = 0; e < ne; e++, o += 6) {
            const a = ea[e], b = eb[e];
            ed[o] = pos[2 * a]; ed[o + 1] = pos[2 * a + 1];
            ed[o + 2] = pos[2 * b]; ed[o + 3] = pos[2 * b + 1];
            ed[o + 4] = q[a]; ed[o + 5] = q[b];
          }
        } else {
          const diff = snap.edge_value;
          for (let e = 0, o = 0; e < ne; e++, o += 6) {
            const a = ea[e], b = eb[e];
            const v = Math.abs(diff[e]);
            ed[o] = pos[2 * a]; ed[o + 1] = pos[2 * a + 1];
            ed[o + 2] = pos[2 * b]; ed[o + 3] = pos[2 * b + 1];
            ed[o + 4] = v; ed[o + 5] = v;
          }
        }
        const pinned = snap.pinned, held = snap.held, md = markData;
        let nMarks = 0;
        for (let k = 0; k < nv; k++) {
          const pk = pinned[k], h = held[k];
          if (pk === 0 && h === 0) continue;
          md[3 * nMarks] = pos[2 * k]; md[3 * nMarks + 1] = pos[2 * k + 1];
          md[3 * nMarks + 2] = h === 0 ? 0 : (pk === 0 ? 1 : 2);
          nMarks++;
        }

        // The panel's rectangle in device pixels (GL's y runs up); the shaders work in
        // device pixels of that rectangle.
        const px = canvas.width / r.cssWidth, b = box();
        const vx = Math.round(b.x * px), vw = Math.round((b.x + b.w) * px) - vx;
        const vtop = Math.round(b.y * px), vh = Math.round((b.y + b.h) * px) - vtop;
        gl.viewport(vx, canvas.height - vtop - vh, vw, vh);
        const offX = (ox - b.x) * px + (b.x * px - vx), offY = (oy - b.y) * px + (b.y * px - vtop);

        if (fill && nCellIdx > 0) {
          gl.bindBuffer(gl.ARRAY_BUFFER, cellBuf);
          gl.bufferSubData(gl.ARRAY_BUFFER, 0, cellView);
          useColoured(cellProg, px, offX, offY, vw, vh, stressMode, scale);
          for (let i = 2; i <= 3; i++) gl.disableVertexAttribArray(i);
          gl.enableVertexAttribArray(0);
          gl.enableVertexAttribArray(1);
          inst.divisor(0, 0);
          inst.divisor(1, 0);
          gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 12, 0);
          gl.vertexAttribPointer(1, 1, gl.FLOAT, false, 12, 8);
          gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, cellIdxBuf);
          gl.drawElements(gl.TRIANGLES, nCellIdx, gl.UNSIGNED_INT, 0);
          r.drawCalls++;
        }
        if (nd > 0 && perRow > 0) {
          gl.bindTexture(gl.TEXTURE_2D, edgeTex);
          gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, 3 * perRow, Math.ceil(nd / perRow), gl.RG, gl.FLOAT, edgeData, 0);
          useColoured(fetchProg, px, offX, offY, vw, vh, stressMode, scale);
          gl.uniform1f(fetchProg.u.u_halfWidth, halfWidth(px));
          gl.uniform1i(fetchProg.u.u_perRow, perRow);
          gl.uniform1i(fetchProg.u.u_edges, 0);
          for (let i = 0; i <= 3; i++) gl.disableVertexAttribArray(i);
          gl.drawArrays(gl.TRIANGLES, 0, 6 * nd);
          r.drawCalls++;
        } else if (nd > 0) {
          gl.bindBuffer(gl.ARRAY_BUFFER, edgeBuf);
          gl.bufferSubData(gl.ARRAY_BUFFER, 0, edgeView);
          useColoured(edgeProg, px, offX, offY, vw, vh, stressMode, scale);
          gl.uniform1f(edgeProg.u.u_halfWidth, halfWidth(px));
          gl.bindBuffer(gl.ARRAY_BUFFER, cornerBuf);
          gl.enableVertexAttribArray(0);
          gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 0, 0);
          inst.divisor(0, 0);
          gl.bindBuffer(gl.ARRAY_BUFFER, edgeBuf);
          for (let i = 1; i <= 3; i++) { gl.enableVertexAttribArray(i); inst.divisor(i, 1); }
          gl.vertexAttribPointer(1, 2, gl.FLOAT, false, 24, 0);
          gl.vertexAttribPointer(2, 2, gl.FLOAT, false, 24, 8);
          gl.vertexAttribPointer(3, 2, gl.FLOAT, false, 24, 16);
          inst.draw(gl.TRIANGLE_STRIP, 0, 4, nd);
          r.drawCalls++;
          inst.divisor(3, 0);
          gl.disableVertexAttribArray(3);
        }
        if (nMarks > 0) {
          gl.bindBuffer(gl.ARRAY_BUFFER, markBuf);
          // WebGL2 uploads just the used part with no view object; WebGL1 sends it all.
          if (version === 2) gl.bufferSubData(gl.ARRAY_BUFFER, 0, markData, 0, 3 * nMarks);
          else gl.bufferSubData(gl.ARRAY_BUFFER, 0, markData);
          gl.useProgram(markProg.prog);
          const u = markProg.u;
          gl.uniform2f(u.u_scale, s * px, -s * px);
          gl.uniform2f(u.u_offset, offX, offY);
          gl.uniform2f(u.u_viewport, vw, vh);
          gl.uniform1f(u.u_pinRadius, PIN_RADIUS_CSS * px);
          gl.uniform1f(u.u_heldRadius, HELD_RADIUS_CSS * px);
          gl.uniform1f(u.u_px, px);
          gl.bindBuffer(gl.ARRAY_BUFFER, markCornerBuf);
          gl.enableVertexAttribArray(0);
          gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 0, 0);
          inst.divisor(0, 0);
          gl.bindBuffer(gl.ARRAY_BUFFER, markBuf);
          gl.enableVertexAttribArray(1);
          gl.enableVertexAttribArray(2);
          inst.divisor(1, 1);
          inst.divisor(2, 1);
          gl.vertexAttribPointer(1, 2, gl.FLOAT, false, 12, 0);
          gl.vertexAttribPointer(2, 1, gl.FLOAT, false, 12, 8);
          inst.draw(gl.TRIANGLE_STRIP, 0, 4, nMarks);
          r.drawCalls++;
        }
      };
      return p;
    }

    // RGBA of the device pixel under each canvas-relative CSS point [cx, cy] (tests only;
    // valid right after draw() in the same task): the drawing buffer read once, not a
    // read a point (each a wait for the GPU: 10,000 points took SwiftShader 20 s); [0, 0, 0,
    // 0] outside it, as a read there gives.
    r.readPixels = function (points) {
      const w = canvas.width, h = canvas.height, px = w / r.cssWidth;
      const all = new Uint8Array(4 * w * h);
      gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, all);
      return points.map(function (p) {
        const x = Math.floor(p[0] * px), y = h - 1 - Math.floor(p[1] * px);
        if (!(x >= 0 && x < w && y >= 0 && y < h)) return [0, 0, 0, 0];
        const o = 4 * (y * w + x);
        return [all[o], all[o + 1], all[o + 2], all[o + 3]];
      });
    };

    return r;
  }

  return { create: create, STRAIN_BASE: STRAIN_BASE };
})();
