// The server's API: one POST per question, answered with a report or {"error":{kind,message}}.
// Failures never throw: a request that cannot reach the server becomes an error like any other.

/** POST `body` as JSON to `path`: {ok: answer} or {error: {kind, message}, status}. */
export async function post(path, body) {
  let response;
  try {
    response = await fetch(path, {
      method: 'POST',
      headers: { 'Content-Type': 'application/json' },
      body: JSON.stringify(body),
    });
  } catch (e) {
    return {
      error: {
        kind: 'network',
        message: `the server did not answer (${e.message}); is lac serve still running?`,
      },
      status: 0,
    };
  }
  let json = null;
  try {
    json = await response.json();
  } catch {
    // Not JSON: reported below.
  }
  if (response.ok && json) return { ok: json };
  const error = json && json.error
    ? json.error
    : { kind: 'internal', message: `the server answered ${response.status} without a report` };
  return { error, status: response.status };
}
