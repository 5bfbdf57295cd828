// Undo/redo over immutable states: every edit pushes the state it replaced.
export class History<T> {
  private past: T[] = [];
  private future: T[] = [];

  constructor(
    private state: T,
    private readonly limit = 200,
  ) {}

  get current(): T {
    return this.state;
  }
  get canUndo(): boolean {
    return this.past.length > 0;
  }
  get canRedo(): boolean {
    return this.future.length > 0;
  }

  /** Records an edit. A no-op edit (same object) records nothing. */
  push(next: T): void {
    if (next === this.state) return;
    this.past.push(this.state);
    if (this.past.length > this.limit) this.past.shift();
    this.future = [];
    this.state = next;
  }

  /** Replaces the current state without a new undo step (an edit continued, e.g. a colour
   *  being dragged): undo goes back to the state before the whole gesture. */
  replace(next: T): void {
    if (next === this.state) return;
    this.future = [];
    this.state = next;
  }

  undo(): boolean {
    const prev = this.past.pop();
    if (prev === undefined) return false;
    this.future.push(this.state);
    this.state = prev;
    return true;
  }

  redo(): boolean {
    const next = this.future.pop();
    if (next === undefined) return false;
    this.past.push(this.state);
    this.state = next;
    return true;
  }

  /** Replaces the whole history (e.g. loading a session). */
  reset(state: T): void {
    this.past = [];
    this.future = [];
    this.state = state;
  }
}
