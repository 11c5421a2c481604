// The HTML report's page code (engine/reporting/html/report_writer.h writes the pages): the index or a
// case page, from the JSON the page carries inline (a page opened from file:// may not fetch).
import 'uplot/dist/uPlot.min.css';
import '../style.css';
import './report.css';
import { el } from '../dom';
import { renderCase } from './case_page';
import { renderIndex } from './index_page';
import type { CaseData, IndexData } from './types';

function inline<T>(id: string): T | null {
  const script = document.getElementById(id);
  return script ? (JSON.parse(script.textContent ?? 'null') as T) : null;
}

function start(): void {
  const host = document.getElementById('report') as HTMLElement;
  try {
    const index = inline<IndexData>('index-data');
    if (index) return renderIndex(host, index);
    const data = inline<CaseData>('case-data');
    if (data) return renderCase(host, data);
    host.replaceChildren(el('p', { class: 'error' }, 'This page carries no report data.'));
  } catch (e) {
    host.replaceChildren(el('p', { class: 'error' }, `The report could not be shown: ${String(e)}`));
  }
}

start();
