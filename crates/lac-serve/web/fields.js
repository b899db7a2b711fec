// The panel's number fields: text read the way a designer means it, or marked with the reason
// it is not used. A field whose text is not the value the curve uses says so, beside it (a small
// note, the field's tooltip and aria-invalid), and the design keeps its last good value.

/** A number as a designer writes it: digits with an optional point and exponent. */
const NUMBER = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;
/** The same with a decimal comma instead of the point (1,5 or -0,25e3), and nothing else. */
const COMMA = /^[+-]?(\d+,\d*|,\d+)([eE][+-]?\d+)?$/;

/** The words of a field's range {above, from, below, to, whole} (above and below exclusive,
 * from and to inclusive, whole: integers only), e.g. "> 0 and < 1", "a whole number ≥ 1". */
export function rangeWords({ above, from, below, to, whole }) {
  const lo = above !== undefined ? `> ${above}` : from !== undefined ? `≥ ${from}` : '';
  const hi = below !== undefined ? `< ${below}` : to !== undefined ? `≤ ${to}` : '';
  const bounds = [lo, hi].filter(Boolean).join(' and ');
  return whole ? `a whole number ${bounds}`.trim() : bounds;
}

const inRange = (x, { above, from, below, to, whole }) =>
  !(above !== undefined && !(x > above)) && !(from !== undefined && !(x >= from))
  && !(below !== undefined && !(x < below)) && !(to !== undefined && !(x <= to))
  && !(whole && !Number.isInteger(x));

/**
 * Read a field's text: {value} when it is a number the curve can use (with `note` when it was
 * read in a way to be told, a decimal comma), or {error} saying why not. `range`: the values
 * allowed ({above, from, below, to, whole}, see rangeWords).
 */
export function readNumber(text, range = {}) {
  const t = text.trim();
  if (t === '') return { error: 'empty' };
  let source = t;
  let note = null;
  if (COMMA.test(t)) {
    source = t.replace(',', '.');
    note = 'decimal comma';
  } else if (t.includes(',')) {
    return { error: 'not a number (write decimals with a point: 1.5)' };
  }
  if (!NUMBER.test(source)) return { error: 'not a number' };
  const value = Number(source);
  if (!Number.isFinite(value)) return { error: 'too large (numbers end near ±1.8e308)' };
  if (value === 0 && /[1-9]/.test(source.replace(/[eE].*$/, ''))) return { error: 'too close to 0 for a number: write 0' };
  if (!inRange(value, range)) return { error: `out of range: must be ${rangeWords(range)}` };
  return note ? { value, note: `${note}: read as ${value}` } : { value };
}

/** The note under each row of fields, and the row's fields. */
const rows = new WeakMap();

/**
 * A number field (a text input: the browser's number input turns "1,5" into 15 and hides the
 * text it cannot read). Every edit is read (`range`: the values allowed); a number the curve
 * can use goes to `onValue(value, eventTime)`; any other text marks the field, and its row's
 * note says why and which value the curve keeps (`inUse()`), called `name`. Leaving the field
 * calls `onCommit()`; a decimal comma is then written with a point. The arrow keys step the
 * value by `step` (`log`: by a factor of 10^step), ten times as far with Shift, as the
 * browser's number field did.
 */
export function numberField({ id, ariaLabel, name, range = {}, step = 0.1, log = false, inUse, onValue, onCommit }) {
  const field = document.createElement('input');
  field.type = 'text';
  field.autocomplete = 'off';
  field.spellcheck = false;
  field.className = 'num';
  if (id) field.id = id;
  if (ariaLabel) field.setAttribute('aria-label', ariaLabel);
  field.addEventListener('input', (e) => {
    const reading = readNumber(field.value, range);
    if (reading.value !== undefined) onValue(reading.value, e.timeStamp);
    mark(field, reading.error || reading.note ? reading : null, name, inUse());
  });
  field.addEventListener('change', () => {
    const reading = readNumber(field.value, range);
    if (reading.note) showValue(field, reading.value);
    onCommit();
  });
  field.addEventListener('keydown', (e) => {
    if (e.key !== 'ArrowUp' && e.key !== 'ArrowDown') return;
    const reading = readNumber(field.value, range);
    const from = reading.value ?? inUse();
    const by = (e.key === 'ArrowUp' ? 1 : -1) * step * (e.shiftKey ? 10 : 1);
    const value = log ? +(from * 10 ** by).toPrecision(3) : +(from + by).toPrecision(12);
    e.preventDefault();
    if (readNumber(String(value), range).error) return;
    showValue(field, value);
    onValue(value, e.timeStamp);
    onCommit();
  });
  return field;
}

/** The note under a row of fields, which says why a field's text is not what the curve
 * uses. */
export function fieldNote(id, fields) {
  const note = document.createElement('div');
  note.className = 'field-note';
  note.id = id;
  note.hidden = true;
  note.setAttribute('aria-live', 'polite');
  for (const field of fields) rows.set(field, { note, fields });
  return note;
}

/** Show `value` in `field`: its text is the value in use again. */
export function showValue(field, value) {
  field.value = String(value);
  mark(field, null);
}

/** Mark `field` after reading its text ({error}: invalid; {note}: read in a way to be told;
 * null: its text is the value in use), and write its row's note. */
function mark(field, reading, name, inUse) {
  const bad = !!(reading && reading.error);
  field.classList.toggle('invalid', bad);
  field.classList.toggle('noted', !bad && !!reading);
  if (bad) field.setAttribute('aria-invalid', 'true');
  else field.removeAttribute('aria-invalid');
  const row = rows.get(field);
  if (reading) {
    const text = bad ? `${name}: ${reading.error}; the curve keeps ${inUse}` : `${name}: ${reading.note}`;
    field.title = text;
    field.dataset.message = text;
    if (row) field.setAttribute('aria-describedby', row.note.id);
  } else {
    field.removeAttribute('title');
    delete field.dataset.message;
    field.removeAttribute('aria-describedby');
  }
  if (!row) return;
  const texts = row.fields.map((f) => f.dataset.message).filter(Boolean);
  row.note.textContent = texts.join('\n');
  row.note.hidden = texts.length === 0;
  row.note.classList.toggle('bad', row.fields.some((f) => f.classList.contains('invalid')));
}
