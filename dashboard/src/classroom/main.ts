// The trainer's overview of a classroom (`vplant classroom`, docs/classroom.md): every seat's
// nodes and exercise progress, refreshed every second from GET /api/seats; restart a seat; give
// every seat the same exercise. All URLs are relative to the page (served at /).
import '../style.css';
import './classroom.css';
import { button, el } from '../dom';
import { seatCard } from './seat_card';
import type { SeatAnswer, SeatSummary } from './types';

const REFRESH_MS = 1000;

async function call<T>(method: string, path: string, body?: unknown): Promise<{ status: number; data: T | null }> {
  const res = await fetch(path, {
    method,
    headers: body === undefined ? {} : { 'Content-Type': 'application/json' },
    body: body === undefined ? undefined : JSON.stringify(body),
  });
  const text = await res.text();
  let data: T | null = null;
  try {
    data = text ? (JSON.parse(text) as T) : null;
  } catch {
    data = null;
  }
  return { status: res.status, data };
}

const messages = document.getElementById('messages') as HTMLElement;
function say(text: string, bad = false): void {
  messages.replaceChildren(el('p', { class: bad ? 'error' : 'info' }, text));
}

function failures(answers: SeatAnswer[]): string {
  return answers
    .filter((a) => a.status >= 300)
    .map((a) => `seat ${a.seat}: ${a.answer?.error ?? a.status}`)
    .join('; ');
}

async function restart(seat: number): Promise<void> {
  const r = await call<SeatAnswer & { error?: string }>('POST', `api/seats/${seat}/restart`, {});
  if (r.status < 300) say(`Seat ${seat} restarted.`);
  else say(`Seat ${seat} was not restarted: ${r.data?.answer?.error ?? r.data?.error ?? r.status}`, true);
  await refresh();
}

async function giveExercise(name: string): Promise<void> {
  if (!name) return say('Choose an exercise first.', true);
  const r = await call<{ seats?: SeatAnswer[]; error?: string }>('POST', 'api/seats/exercise', { name });
  const bad = r.data?.seats ? failures(r.data.seats) : r.data?.error ?? String(r.status);
  if (r.status < 300) say(`Every seat has the exercise "${name}".`);
  else say(`The exercise "${name}" was not given everywhere: ${bad}`, true);
  await refresh();
}

/** The exercise chooser: the names seat 1 offers (every seat has the same folder). */
async function exerciseControls(): Promise<void> {
  const host = document.getElementById('exercise-controls') as HTMLElement;
  const r = await call<string[] | { name: string; title?: string }[]>('GET', 'seats/1/api/exercises');
  if (r.status !== 200 || !Array.isArray(r.data)) {
    host.replaceChildren(el('p', { class: 'muted' }, 'This classroom has no exercises (start it with --exercises DIR).'));
    return;
  }
  const names = r.data.map((e) => (typeof e === 'string' ? e : e.name));
  const select = el('select', { 'data-testid': 'exercise-choice', 'aria-label': 'exercise' }, ...names.map((n) => el('option', { value: n }, n)));
  host.replaceChildren(select, button('Give to every seat', { 'data-testid': 'give-exercise' }, () => void giveExercise(select.value)));
}

const seatsHost = document.getElementById('seats') as HTMLElement;
const connection = document.getElementById('connection') as HTMLElement;

async function refresh(): Promise<void> {
  try {
    const r = await call<{ seats: SeatSummary[] }>('GET', 'api/seats');
    if (r.status !== 200 || !r.data) throw new Error(`GET /api/seats: ${r.status}`);
    seatsHost.replaceChildren(...r.data.seats.map((s) => seatCard(s, { restart: (k) => void restart(k) })));
    connection.textContent = 'live';
    connection.dataset.open = 'true';
  } catch (e) {
    connection.textContent = `offline (${String(e)})`;
    connection.dataset.open = 'false';
  }
}

void exerciseControls();
void refresh();
setInterval(() => void refresh(), REFRESH_MS);
