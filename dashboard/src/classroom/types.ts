// The trainer's endpoints (docs/api.md, "Classroom"): what GET /api/seats answers.
import type { ClockState, NodeInfo } from '../types';

/** GET /seats/K/api/exercise (docs/exercises.md). */
export interface ExerciseProgress {
  name: string;
  title?: string;
  steps: { title: string; done: boolean; t_us?: number | null }[];
}

export interface SeatSummary {
  seat: number;
  running: boolean;
  nodes: NodeInfo[];
  clock: ClockState | null;
  exercise: ExerciseProgress | null;
  lateness_us: { ticks: number; p50: number; p99: number; max: number } | null;
}

/** The answer of a seat to an action the overview passed on (restart, exercise). */
export interface SeatAnswer {
  seat: number;
  status: number;
  answer: { error?: string } | null;
}
