// The server's HTTP API (docs/dnc-server.md), with the login's token kept
// for this tab only.

export interface CheckDiagnostic {
  code: string;
  severity: string;
  line: number;
  column: number;
  message: string;
}

export interface Checks {
  dialect: string;
  errors: number;
  warnings: number;
  complete: boolean;
  diagnostics: CheckDiagnostic[];
  cycle_time_s: number;
  cutting_s?: number;
  rapid_s?: number;
  overtravel?: number;
  bounds: { min: number[]; max: number[] } | null;
  checks?: Record<string, number>; // stats check code -> count
}

export interface Revision {
  revision: string;
  state: string;
  author: string;
  reason: string;
  size: number;
  created_at_us: number;
  state_at_us: number;
  check_ok: boolean;
  checks: Checks | null;
}

export interface ProgramSummary {
  name: string;
  machine_class: string;
  dialect: string;
  // In the library's list (GET /api/programs), not in a program's own page.
  newest_state?: string;
  released_revision?: string | null;
}

// A page of the library (GET /api/programs): `total` counts every program
// the filters match; `machine_classes` are those of the whole library.
export interface LibraryList {
  programs: ProgramSummary[];
  total: number;
  limit: number;
  offset: number;
  machine_classes?: string[];
}

export interface Program extends ProgramSummary {
  released: string | null;
  revisions: Revision[];
}

export interface Job {
  job: number;
  machine: string;
  program: string;
  revision: string;
  mode: string; // send | drip
  state: string; // queued | running | done | interrupted | failed
  user: string;
  bytes_sent: number;
  bytes_total: number;
  line: number;
  block: number | null;
  reason: string;
  alarm: boolean;
  created_at_us: number;
  started_at_us: number | null; // by the server's clock
  ended_at_us: number | null;
}

export interface Machine {
  name: string;
  dialect: string;
  machine_class: string;
  mode: string;
  port: string;
  state: string;
  link_error: string;
  job: Job | null;
  queue?: number[];
  part_count?: number;
  last_cycle_seconds?: number | null;
  last_message?: string;
}

export interface Diff {
  from: string;
  to: string;
  normalised: boolean;
  identical: boolean;
  deleted: number;
  inserted: number;
  diff: string; // unified
}

export class ApiError extends Error {
  constructor(
    readonly status: number,
    message: string,
    readonly body?: unknown, // the answer's JSON, when it was (a form's 400 names its fields)
  ) {
    super(message);
  }
}

const TOKEN = 'usina.token';

export function token(): string {
  return sessionStorage.getItem(TOKEN) ?? '';
}

export function setToken(t: string): void {
  if (t) sessionStorage.setItem(TOKEN, t);
  else sessionStorage.removeItem(TOKEN);
}

async function call(method: string, path: string, body?: unknown, signal?: AbortSignal): Promise<Response> {
  const headers: Record<string, string> = {};
  const sent = token();
  if (sent) headers['Authorization'] = `Bearer ${sent}`;
  if (body !== undefined) headers['Content-Type'] = 'application/json';
  const res = await fetch(path, {
    method,
    headers,
    body: body === undefined ? undefined : JSON.stringify(body),
    signal,
  });
  if (!res.ok) {
    let message = `${res.status} ${res.statusText}`;
    let j: { error?: string } | undefined;
    try {
      j = (await res.json()) as { error?: string };
      if (j.error) message = j.error;
    } catch {
      /* not JSON: keep the status line */
    }
    // Only the session this request was sent with has ended: an answer to a
    // request of the last session, arriving after the next login, must not
    // log the new session out.
    if (res.status === 401 && token() === sent) setToken('');
    throw new ApiError(res.status, message, j);
  }
  return res;
}

// `signal` cancels the request (a newer one replaced it).
export async function getJson<T>(path: string, signal?: AbortSignal): Promise<T> {
  return (await (await call('GET', path, undefined, signal)).json()) as T;
}

export async function postJson<T>(path: string, body: unknown): Promise<T> {
  return (await (await call('POST', path, body)).json()) as T;
}

export async function getText(path: string): Promise<string> {
  return (await call('GET', path)).text();
}

export async function getBytes(path: string): Promise<ArrayBuffer> {
  return (await call('GET', path)).arrayBuffer();
}

// A file of the API (a drawing) with its answer's headers: the page shows
// it through an object URL, never as markup of its own.
export async function getFile(path: string): Promise<{ blob: Blob; headers: Headers }> {
  const res = await call('GET', path);
  return { blob: await res.blob(), headers: res.headers };
}

export const enc = encodeURIComponent;
