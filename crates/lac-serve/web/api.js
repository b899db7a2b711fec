// The server's API: one POST per question, answered with a report or {"error":{kind,message}}.
// Failures never throw: a request that cannot reach the server becomes an error like any other.

/** POST `body` as JSON to `path`: {response}, or {error, status: 0} when the server cannot
 * be reached (or `signal` aborted the request). */
async function send(path, body, signal) {
  try {
    const response = await fetch(path, {
      method: 'POST',
      headers: { 'Content-Type': 'application/json' },
      body: JSON.stringify(body),
      signal,
    });
    return { response };
  } catch (e) {
    return {
      error: {
        kind: 'network',
        message: `the server did not answer (${e.message}); is lac serve still running?`,
      },
      status: 0,
    };
  }
}

/** POST `body` as JSON to `path`: {ok: answer} or {error: {kind, message}, status}.
 * `signal` (an AbortController's) may abort it. */
export async function post(path, body, signal) {
  const { response, error, status } = await send(path, body, signal);
  if (!response) return { error, status };
  let json = null;
  try {
    json = await response.json();
  } catch {
    // Not JSON: reported below.
  }
  if (response.ok && json) return { ok: json };
  const failure = json && json.error
    ? json.error
    : { kind: 'internal', message: `the server answered ${response.status} without a report` };
  return { error: failure, status: response.status };
}

/** POST `body` as JSON to `path`, whose answer is a file: {ok: {text, type, name, report}}
 * (`report` from the X-Lac-Export header, or null) or {error: {kind, message}, status}. */
export async function postFile(path, body) {
  const { response, error: unreachable, status } = await send(path, body);
  if (!response) return { error: unreachable, status };
  const text = await response.text();
  if (!response.ok) {
    let error = null;
    try {
      error = JSON.parse(text).error;
    } catch {
      // Not JSON: reported below.
    }
    return {
      error: error || { kind: 'internal', message: `the server answered ${response.status}` },
      status: response.status,
    };
  }
  const disposition = response.headers.get('Content-Disposition') || '';
  const name = (disposition.match(/filename="([^"]+)"/) || [])[1] || 'lac-curve';
  let report = null;
  try {
    report = JSON.parse(response.headers.get('X-Lac-Export'));
  } catch {
    // No report: the file is still good.
  }
  return { ok: { text, type: response.headers.get('Content-Type') || '', name, report } };
}
