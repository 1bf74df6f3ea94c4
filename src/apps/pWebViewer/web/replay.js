// Replay: the state at MOOS time t is every mail with time <= t applied in order through
// applyMail, then expire(t). Moving forward applies the next mails; moving back rebuilds.
import { stateForHello, applyMail, expire } from './state.js';

export class Replay {
  /** `data` = {hello, mail: [...]} as GET /replay.json or window.VIEWER_REPLAY give it. */
  constructor(data) {
    this.hello = data.hello || {};
    // A stable sort: mails of equal time keep their log order.
    this.mail = (data.mail || []).filter((m) => m && m.type === 'mail' && Number.isFinite(m.time))
      .map((m, i) => [m, i]).sort((a, b) => a[0].time - b[0].time || a[1] - b[1]).map((p) => p[0]);
    this.start = this.mail.length ? this.mail[0].time : (this.hello.time || 0);
    this.end = this.mail.length ? this.mail[this.mail.length - 1].time : this.start;
    this.speed = 1;
    this.playing = false;
    this.reset();
  }

  reset() {
    this.state = stateForHello(this.hello, 'replay');
    this.state.time = this.start;
    this.next = 0;
    this.t = this.start;
  }

  /** Moves to MOOS time t (clamped to the log). */
  seek(t) {
    t = Math.max(this.start, Math.min(this.end, t));
    if (t < this.t) this.reset();
    while (this.next < this.mail.length && this.mail[this.next].time <= t) {
      applyMail(this.state, this.mail[this.next++]);
    }
    expire(this.state, t);
    this.state.time = t;
    this.t = t;
    this.state.version++;
  }

  /** Advances by wall-clock seconds dt at the chosen speed; stops at the end. */
  tick(dt) {
    if (!this.playing) return;
    this.seek(this.t + dt * this.speed);
    if (this.t >= this.end) this.playing = false;
  }
}
