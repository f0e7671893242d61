// Who may do what, as the server's table says (src/dnc/store_roles.cpp,
// docs/dnc.md "Roles"). The page uses it only to hide or disable what a
// role may not do; the server decides, and its 403 is shown when it says no.
import { getJson, token } from './api';

export type Role = 'operator' | 'programmer' | 'approver' | 'admin';

export interface SessionUser {
  user: string;
  role: Role;
}

let cached: { token: string; user: Promise<SessionUser> } | null = null;

// The logged-in user, asked once per login.
export function sessionUser(): Promise<SessionUser> {
  if (!cached || cached.token !== token()) cached = { token: token(), user: getJson<SessionUser>('/api/session') };
  return cached.user;
}

// Send, drip feed, start from a block or tool, stop (Permission::StartJob).
export function mayRunJobs(role: Role): boolean {
  return role === 'operator' || role === 'programmer' || role === 'admin';
}

// Record a quality measurement (Permission::RecordQuality).
export function mayRecordQuality(role: Role): boolean {
  return role === 'operator' || role === 'approver' || role === 'admin';
}

export function mayUpload(role: Role): boolean {
  return role === 'programmer' || role === 'admin';
}

interface StateGrant {
  from: string;
  to: string;
  roles: Role[];
  fourEyes: boolean; // not by the revision's author (admins excepted)
}

const STATE_GRANTS: StateGrant[] = [
  { from: 'draft', to: 'checked', roles: ['programmer', 'approver', 'admin'], fourEyes: false },
  { from: 'draft', to: 'rejected', roles: ['programmer', 'approver', 'admin'], fourEyes: false },
  { from: 'checked', to: 'approved', roles: ['approver', 'admin'], fourEyes: true },
  { from: 'checked', to: 'rejected', roles: ['approver', 'admin'], fourEyes: false },
  { from: 'approved', to: 'released', roles: ['approver', 'admin'], fourEyes: true },
  { from: 'approved', to: 'rejected', roles: ['approver', 'admin'], fourEyes: false },
  { from: 'released', to: 'rejected', roles: ['approver', 'admin'], fourEyes: false },
];

// The moves out of `from` (the state graph's edges a person makes).
export function movesFrom(from: string): string[] {
  return STATE_GRANTS.filter((g) => g.from === from).map((g) => g.to);
}

// Why `who` may not move a revision of `author` from `from` to `to`; empty when they may.
export function whyNot(who: SessionUser, author: string, from: string, to: string): string {
  const g = STATE_GRANTS.find((x) => x.from === from && x.to === to);
  if (!g) return `${from} → ${to} is not a move of the state graph`;
  if (!g.roles.includes(who.role)) return `${from} → ${to} is for ${g.roles.join(', ')}; you are ${who.role}`;
  if (g.fourEyes && who.role !== 'admin' && who.user === author) return `you wrote this revision; ${from} → ${to} needs someone else (four eyes)`;
  return '';
}

// Start a tool's life count again (Permission::ResetToolLife).
export function mayResetTools(role: Role): boolean {
  return role === 'operator' || role === 'programmer' || role === 'admin';
}
