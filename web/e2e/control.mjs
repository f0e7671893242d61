// The simulated ROMI control on the far end of the machine's pty pair (the
// `ctl` link of the harness's socat): it counts every byte the server sends
// and punches machine data back in ISO code (7 bits, even parity on bit 7).
import { closeSync, openSync, read, writeSync } from 'node:fs';

export function iso(text) {
  const out = Buffer.alloc(text.length);
  for (let i = 0; i < text.length; i++) {
    let c = text.charCodeAt(i) & 0x7f;
    let ones = 0;
    for (let b = c; b; b >>= 1) ones += b & 1;
    if (ones % 2) c |= 0x80;
    out[i] = c;
  }
  return out;
}

// The 7-bit text of what arrived (parity stripped).
export function text(bytes) {
  return Buffer.from(bytes.map((b) => b & 0x7f)).toString('latin1');
}

export class Control {
  constructor(path) {
    this.fd = openSync(path, 'r+');
    this.received = [];
    this.open = true;
    this.pump();
  }

  // Reads on libuv's pool, one read in flight at a time.
  pump() {
    const buf = Buffer.alloc(4096);
    read(this.fd, buf, 0, buf.length, null, (err, n) => {
      if (err || !this.open) return;
      for (let i = 0; i < n; i++) this.received.push(buf[i]);
      this.pump();
    });
  }

  mark() {
    return this.received.length;
  }

  since(mark) {
    return this.received.slice(mark);
  }

  punch(textToSend) {
    writeSync(this.fd, iso(textToSend));
  }

  close() {
    this.open = false;
    try {
      closeSync(this.fd);
    } catch {
      /* closed already */
    }
  }
}
