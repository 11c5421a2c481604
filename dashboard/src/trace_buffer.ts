// The trace's memory: the newest frames up to a cap (a browser tab must not grow without bound),
// and a pause that freezes what is shown while frames keep arriving.
import type { Frame } from './types';

export class TraceBuffer {
  private frames: Frame[] = [];
  private frozen: Frame[] | null = null;
  private droppedCount = 0;

  constructor(readonly capacity: number) {}

  push(batch: readonly Frame[]): void {
    this.frames.push(...batch);
    const excess = this.frames.length - this.capacity;
    if (excess > 0) {
      this.frames.splice(0, excess);
      this.droppedCount += excess;
    }
  }

  /** Frames forgotten because the buffer was full (the oldest go first). */
  get dropped(): number {
    return this.droppedCount;
  }

  get paused(): boolean {
    return this.frozen !== null;
  }

  pause(): void {
    if (!this.frozen) this.frozen = this.frames.slice();
  }

  resume(): void {
    this.frozen = null;
  }

  /** What the view shows: the snapshot taken at pause, else everything kept. */
  shown(): readonly Frame[] {
    return this.frozen ?? this.frames;
  }

  clear(): void {
    this.frames = [];
    if (this.frozen) this.frozen = [];
  }
}
