// Session versions and the migrations between them.
//
// A saved session says which shape it has in `version`. The strict reader (sessionFile.ts) reads
// only the current shape; an older session is first brought to it here, by named steps, each a
// pure function from one version's plain JSON to the next one's (`v1-to-v2: …`). A session from a
// version newer than this build knows is refused with a message saying so, never guessed at.
//
// To change the shape: bump SESSION_VERSION (and SessionState['version'] in
// session.ts), make the reader read the new shape, and add the step from the old version here,
// with a test that an old session comes out as the new one.

/** JSON data as the reader's first pass copies it: null-prototype records, arrays, primitives. */
export type Plain = null | boolean | number | string | Plain[] | PlainRecord;
export interface PlainRecord {
  [key: string]: Plain;
}

/** The session shape this build writes and reads. */
export const SESSION_VERSION = 4 as const;

/** One step: reads a session of version `from`, returns it as version `from + 1`. Pure: it must
 *  not modify its argument (the reader's copy may be shared with the caller's error path). */
export interface SessionMigration {
  /** `v<from>-to-v<from+1>: what changes`, shown in tests and logs. */
  readonly name: string;
  readonly from: number;
  migrate(session: Readonly<PlainRecord>): PlainRecord;
}

/** Oldest first; one step per version from the oldest readable one up to SESSION_VERSION. */
export const SESSION_MIGRATIONS: readonly SessionMigration[] = [
  {
    name: 'v1-to-v2: stored scalp-avoidance constraints become the avoidScalp setting',
    from: 1,
    migrate(s) {
      // Version 1 kept "Avoid scalp" as the constraints it made (grid indices and targets, made
      // once from the curves of that moment). Version 2 keeps that it is on; the solver derives
      // the constraints from the current curves whenever it solves them.
      // An `avoid` that is not null or a record with an index array is left in place, so the
      // reader refuses it by name.
      const a = s.avoid;
      const wellFormed =
        a === null || (typeof a === 'object' && !Array.isArray(a) && Array.isArray(a.index));
      const out: PlainRecord = Object.create(null);
      for (const [k, v] of Object.entries(s)) if (k !== 'avoid' || !wellFormed) out[k] = v;
      if (wellFormed && a !== null && (a.index as Plain[]).length > 0) out.avoidScalp = true;
      out.version = 2;
      return out;
    },
  },
  {
    name: 'v2-to-v3: the head may be a loaded mesh; version 2 sessions are on the built-in head',
    from: 2,
    migrate(s) {
      // Version 3 adds a head mesh (head: {kind: 'mesh', …}), scalp brush strokes (scalpPaint)
      // and a mirror plane (symmetry), all optional. A version 2 session is on the built-in
      // head, and says so. A `head` other than absent or "builtin" is left in place for the
      // reader to check as version 3 data.
      const out: PlainRecord = Object.create(null);
      for (const [k, v] of Object.entries(s)) out[k] = v;
      if (s.head === undefined) out.head = 'builtin';
      out.version = 3;
      return out;
    },
  },
  {
    name: 'v3-to-v4: natural fall is a setting; sessions made before it stay without it',
    from: 3,
    migrate(s) {
      // Version 4 adds `fall` (hair no curve governs hangs, a curve's hair ends where the curve
      // ends, curves may take hair over the face), on in new sessions. A version 3 session has
      // no `fall`: it keeps the paper's method and so exactly the hair it had.
      const out: PlainRecord = Object.create(null);
      for (const [k, v] of Object.entries(s)) out[k] = v;
      out.version = 4;
      return out;
    },
  },
];

export type Migrated =
  | { ok: true; value: PlainRecord; applied: string[] }
  | { ok: false; error: string };

export interface MigrationTable {
  migrations: readonly SessionMigration[];
  current: number;
}

/** The oldest version a table can read: the first step's `from`, or the current version. */
export function oldestVersion(table: MigrationTable): number {
  return table.migrations.reduce((m, s) => Math.min(m, s.from), table.current);
}

/** Brings a session (its `version` field says which) to `table.current` by the table's steps,
 *  in order; says which steps ran. Refuses a missing or non-integer version, a version older
 *  than the table reaches and one newer than it knows, naming `session.version`. */
export function migrateSession(
  session: Readonly<PlainRecord>,
  table: MigrationTable = { migrations: SESSION_MIGRATIONS, current: SESSION_VERSION },
): Migrated {
  const { current } = table;
  const oldest = oldestVersion(table);
  const range = oldest === current ? `${current}` : `an integer from ${oldest} to ${current}`;
  const v = Object.hasOwn(session, 'version') ? session.version : undefined;
  if (v === undefined) return fail(`session.version: missing (must be ${range})`);
  if (typeof v !== 'number' || !Number.isInteger(v))
    return fail(`session.version: must be ${range}`);
  if (v > current)
    return fail(
      `session.version: must be ${range}; version ${v} was made by a newer hairsketch (update hairsketch to open it)`,
    );
  if (v < oldest)
    return fail(`session.version: must be ${range}; version ${v} is older than any hairsketch`);
  let out: Readonly<PlainRecord> = session;
  const applied: string[] = [];
  for (let at = v; at < current; at++) {
    const step = table.migrations.find((m) => m.from === at);
    if (!step) return fail(`session.version: no migration from version ${at} (internal)`);
    let next: PlainRecord;
    try {
      next = step.migrate(out);
    } catch (e) {
      return fail(`session: migration ${step.name} failed (${thrownText(e)})`);
    }
    if (next.version !== at + 1)
      return fail(`session: migration ${step.name} did not give version ${at + 1} (internal)`);
    out = next;
    applied.push(step.name);
  }
  return { ok: true, value: out as PlainRecord, applied };
}

function fail(error: string): Migrated {
  return { ok: false, error };
}

/** A short description of a thrown value that cannot itself throw. */
function thrownText(e: unknown): string {
  try {
    if (e instanceof Error) return String(e.message).slice(0, 200);
  } catch {
    // a Proxy's getPrototypeOf trap threw
  }
  return 'it threw';
}
