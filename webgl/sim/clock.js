// The simulation's own clock: simulated time follows the wall clock wherever the simulation
// can keep up, whatever the drawing's rate. The core advances a fixed dt a frame; the clock says
// how many frames are due at a wall-clock time (seconds), and keeps simulated time no more
// than MAX_BEHIND behind it: a longer backlog (a stall, a scene too heavy for this machine) is
// dropped, never owed, so the simulation runs in slow motion instead of bursting to catch up,
// and `rate` says by how much (simulated seconds per wall-clock second over the last WINDOW).
// Pure arithmetic on the times it is given (the tests drive it with their own).
export const clothClock = (function () {
  const MAX_BEHIND = 0.25;     // s of simulated time owed at most
  const WINDOW = 1.0;          // s of wall clock the rate is measured over

  function create(dt) {
    return { dt: dt, origin: NaN, frames: 0, windowAt: NaN, windowFrames: 0, rate: 1, behind: 0 };
  }

  // Start (or start again, after a pause or a new scene) at wall-clock time `now`: nothing is
  // owed for the time before it.
  function start(c, now, dt) {
    if (dt > 0) c.dt = dt;
    c.origin = now;
    c.frames = 0;
    c.windowAt = now;
    c.windowFrames = 0;
    c.rate = 1;
    c.behind = 0;
  }

  // The frames due at `now`: those whose time has come and have not run, at most MAX_BEHIND's
  // worth (the rest is dropped: the clock's origin moves on by it).
  function due(c, now) {
    if (!(c.origin === c.origin)) start(c, now, 0);
    const cap = Math.max(1, Math.ceil(MAX_BEHIND / c.dt));
    let n = Math.floor((now - c.origin) / c.dt + 1e-9) - c.frames;
    if (n > cap) {
      c.origin += (n - cap) * c.dt;
      n = cap;
    }
    c.behind = n > 0 ? n * c.dt : 0;
    return n > 0 ? n : 0;
  }

  // `n` frames ran by `now`; the rate over the window is brought up to date.
  function ran(c, n, now) {
    c.frames += n;
    c.windowFrames += n;
    const wall = now - c.windowAt;
    if (wall >= WINDOW) {
      c.rate = c.windowFrames * c.dt / wall;
      c.windowAt = now;
      c.windowFrames = 0;
    }
  }

  // Seconds of wall clock from `now` until the next frame is due (0: one is due now).
  function wait(c, now) {
    const next = c.origin + (c.frames + 1) * c.dt;
    return next > now ? next - now : 0;
  }

  return { MAX_BEHIND: MAX_BEHIND, WINDOW: WINDOW, create: create, start: start, due: due, ran: ran, wait: wait };
})();
