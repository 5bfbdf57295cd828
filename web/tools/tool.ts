// Tools are small state machines fed pointer input; work happens in update(), once per frame.
export interface ToolPointer {
  x: number; // client coordinates
  y: number;
  button: number; // 0 = primary
  shiftKey?: boolean;
}

export interface Tool {
  readonly name: string;
  readonly state: string;
  /** Returns true when the tool takes this press (the camera then ignores it). */
  onPointerDown(p: ToolPointer): boolean;
  onPointerMove(p: ToolPointer): void;
  onPointerUp(p: ToolPointer): void;
  onCancel(): void;
  update(): void;
  /** The wheel over the view; true when the tool used it (the camera then does not zoom). */
  onWheel?(deltaY: number): boolean;
  /** The pointer moved over the view with no press (null: it left the view). */
  onHover?(p: ToolPointer | null): void;
}
