// The exercise beside the plant (docs/exercises.md): its title and introduction, each step's
// instruction and hint, and a done mark with the virtual time the plant saw the goal met. The
// checking is the plant's; this view only shows it, as the stream's `exercise` event brings it
// (on connect, on a selection, when a step is done: no poll). A trainee may choose another
// exercise of the folder (GET /api/exercises once, POST /api/exercise).
import { relative } from '../api';
import { el } from '../dom';

export interface ExerciseStep {
  title: string;
  text: string;
  hint: string;
  goal?: string;
  done: boolean;
  t_us: number | null;
}

export interface ExerciseState {
  name: string | null;
  title: string;
  introduction: string;
  steps: ExerciseStep[];
  current?: number;
  done?: boolean;
}

export type StepStatus = 'done' | 'current' | 'open';

export interface StepRow {
  number: number;
  title: string;
  text: string;
  hint: string;
  status: StepStatus;
  mark: string;  // ✓ done, ▶ the one to do now, nothing for later steps
  time: string;  // "done at 1.234 s" or ""
}

export interface ExerciseModel {
  heading: string;
  introduction: string;
  progress: string;
  rows: StepRow[];
}

/// Virtual time for a done mark: seconds with milliseconds.
export function doneTime(t_us: number): string {
  return `done at ${(t_us / 1e6).toFixed(3)} s`;
}

/// What the view shows for a state (pure: the unit test checks it).
export function exerciseModel(state: ExerciseState): ExerciseModel | null {
  if (state.name === null) return null;
  const firstOpen = state.steps.findIndex((s) => !s.done);
  const done = state.steps.filter((s) => s.done).length;
  const rows = state.steps.map((s, i): StepRow => {
    const status: StepStatus = s.done ? 'done' : i === firstOpen ? 'current' : 'open';
    return {
      number: i + 1,
      title: s.title,
      text: s.text,
      hint: s.hint,
      status,
      mark: status === 'done' ? '✓' : status === 'current' ? '▶' : '',
      time: s.done && s.t_us !== null ? doneTime(s.t_us) : '',
    };
  });
  const progress = done === state.steps.length ? `all ${done} steps done` : `${done} of ${state.steps.length} steps done`;
  return { heading: state.title || state.name, introduction: state.introduction, progress, rows };
}

async function getJson<T>(path: string, body?: unknown): Promise<T> {
  const res = await fetch(relative(path), body === undefined ? {} : {
    method: 'POST',
    headers: { 'Content-Type': 'application/json' },
    body: JSON.stringify(body),
  });
  const parsed = (await res.json().catch(() => ({}))) as T & { error?: string };
  if (!res.ok) throw new Error(parsed.error ?? `${res.status}`);
  return parsed;
}

function renderRow(r: StepRow): HTMLElement {
  const li = el('li', { class: `exercise-step ${r.status}`, 'data-testid': `exercise-step-${r.number}`, 'data-status': r.status },
    el('span', { class: 'exercise-mark', 'aria-hidden': 'true' }, r.mark),
    el('strong', {}, r.title),
    r.time ? el('span', { class: 'exercise-time', 'data-testid': `exercise-time-${r.number}` }, ` ${r.time}`) : null);
  // Only the current step's instruction is open: the list stays short on a projector.
  if (r.status === 'current') {
    li.append(el('p', { class: 'exercise-text' }, r.text));
    if (r.hint) li.append(el('details', { class: 'exercise-hint' }, el('summary', {}, 'Hint'), r.hint));
  }
  return li;
}

export interface ExerciseView {
  /// The stream's `exercise` event.
  show(state: ExerciseState): void;
}

/// Adds the exercise panel at the top of `host`; the caller hands it the stream's events.
export function mountExerciseView(host: HTMLElement): ExerciseView {
  // The whole width of the page's grid: a chooser alone stays one line, and the panels below keep
  // their places whether an exercise is open or not.
  const section = el('section', {
    id: 'exercise-section', 'aria-labelledby': 'exercise-h', 'data-testid': 'exercise', hidden: true, style: 'grid-column: 1 / -1',
  });
  const choose = el('select', { 'aria-label': 'exercise', 'data-testid': 'exercise-choice' });
  const status = el('span', { class: 'exercise-status', role: 'status' });
  const body = el('div', { class: 'exercise-body' });
  choose.addEventListener('change', () => {
    if (!choose.value) return;
    getJson<ExerciseState>('/api/exercise', { name: choose.value })
      .then((s) => show(s))
      .catch((e: Error) => { status.textContent = e.message; });
  });
  section.append(el('h2', { id: 'exercise-h' }, 'Exercise ', choose, ' ', status), body);
  host.prepend(section);
  let last = '';
  let pending: ExerciseState | null = null;  // an event that came before the chooser had its names
  let ready = false;

  function show(state: ExerciseState): void {
    if (!ready) {
      pending = state;
      return;
    }
    const text = JSON.stringify(state);
    if (text === last) return;  // nothing changed: keep the DOM (and an open hint) as it is
    last = text;
    const m = exerciseModel(state);
    choose.value = state.name ?? '';
    body.replaceChildren();
    if (!m) return;
    status.textContent = m.progress;
    body.append(el('h3', { class: 'exercise-title' }, m.heading), el('p', { class: 'exercise-intro' }, m.introduction),
      el('ol', { class: 'exercise-steps' }, ...m.rows.map(renderRow)));
  }

  async function start(): Promise<void> {
    const names = await getJson<string[]>('/api/exercises');
    if (names.length === 0) return;  // no exercises folder: no panel
    choose.append(el('option', { value: '' }, '(none)'), ...names.map((n) => el('option', { value: n }, n)));
    section.hidden = false;
    ready = true;
    if (pending) show(pending);
  }
  void start().catch(() => undefined);
  return { show };
}
