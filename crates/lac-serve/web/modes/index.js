// The editor's modes, one module per curve kind, in the order of the page's buttons. A new
// kind is a new module here and one line in LIST (see ../README.md, "To add a mode").
//
// A mode is one object. Its data:
//   name, label        the link's and the file's word for it (`#mode=name`), the button's text
//   endpoint           the API that solves its design (POST, with `samples`)
//   stage              the element that shows it: 'plane' (#plane) or 'space' (#space)
//   dims, count        numbers per control point; how many points (null: at least `minCount`,
//   minCount           the polygon grows and shrinks; its design may say `closed`, whether
//                      a clicked point may go on the closing leg, edit.js)
//   params             the panel's fields: {key, label, min, max, step, log, boolean, choices, hint,
//                      valid, enabled, bounds}: min and max are the slider's (log10 with `log`;
//                      `bounds(design)`, {min, max} of this design, where they depend on it),
//                      `valid` the values the field accepts ({above, from, below, to, whole},
//                      fields.js; any finite number if absent), `enabled(design)` whether the
//                      field applies (else it is greyed out)
//   controlPolygon     whether it has a control polygon to show (the Show box's option)
//   defaults           the starting design: {points, ...params}
//   fileRank,          a file without "mode" is the design of the first mode, by fileRank,
//   recognises(json)   that recognises it; adopt(json, design) reads what such a file says
//   adopt(json, d)     in words of its own
//   link(design)       the link's fields of what the design holds beyond its points and
//   fromLink(fields, d)  params, as [key, value] pairs; reading them back into design d
//                      (fields: the link's Map), an error message or null
//   menu(design, i)    the menu of control point i (right click): {title, items: [{label,
//                      key, checked, disabled, apply(design, i)}]}, or null for none
//   region(frame)      the drawable region's request {key, path, body, canonical, wide}, or
//                      null (`wide`: the request of a map around a canonical one, or null)
//   regionInView       its region covers the visible plane: asked again when the view moves
// Its functions (a plane mode takes them from ./plane.js and overrides what differs):
//   init(input)        once at start: a mode with views of its own wires them to `input`
//   request(body)      the API request from a copy of the design (with `samples`)
//   check(design)      what the page can tell is wrong with a design without asking the
//                      server, as an error {kind, message} (it is not sent), or null
//   cad(body, answer)  the exact curve's fields of the /api/export request, from a copy
//                      of the design (and the answer it has now)
//   samples(answer)    the curve's samples {s, x, y, [z], theta, kappa, ...}, or []
//   draw(frame)        draw the design and the answer on its stage; returns {evolute: 'off' |
//                      'visible' | 'outside'}, what the page says of the evolute
//   fit(frame)         fit its view(s) to the design and the curve
//   screenOf(frame, i, view)  where control point i is in the window (tests)
//   readout(answer, add, design)  the panel's numbers: add(label, key, value, text?)
//   table(answer, design)  an element under them (or null)
//   pointsPanel({points, apply})  the points' fieldset instead of a field per point (a
//                      fit's hundreds of points): {elements, show(points)}, show called
//                      whenever the points change; apply(points, more) sets them (and the
//                      design's fields in `more`)
//   plots(answer, {hover, error})  {kplot, lcg}: the options of the two plots (plots.js)
//   fix(error, design) a button for a refusal: {label, apply(design)}, or null
//   combLimit(frame)   the largest comb scale at which the teeth stay in view (while dragging)
//   placeMessage(box, frame)  put the message (#message, shown or hidden) where it covers no
//                      control point (banner.js)
//   svg({design, answer, combScale, show, title})  the SVG export
// `frame` is what the page holds now (state.js).

import segment from './segment.js';
import compound from './compound.js';
import compound4 from './compound4.js';
import path from './path.js';
import spline from './spline.js';
import quasi from './quasi.js';
import space from './space.js';
import fit from './fit.js';

const LIST = [segment, compound, compound4, path, spline, quasi, space, fit];

/** What a mode need not say. */
const DEFAULTS = {
  fileRank: Infinity,
  recognises: () => false,
  adopt: () => {},
  link: () => [],
  fromLink: () => null,
  menu: () => null,
  region: null,
  regionInView: false,
  init: () => {},
  controlPolygon: true,
  request: (body) => body,
  check: () => null,
  cad: (body) => body,
  samples: (answer) => (answer && answer.samples) || [],
  table: () => null,
  fix: () => null,
  combLimit: () => Infinity,
  placeMessage: () => {},
};

/** The modes by name. */
export const MODES = Object.fromEntries(LIST.map((m) => [m.name, { ...DEFAULTS, ...m }]));

/** The elements that show a mode: all hidden but the current mode's. */
export const STAGES = [...new Set(LIST.map((m) => m.stage))];

/** The mode of a file that does not say its mode. */
export const recognise = (json) => Object.values(MODES)
  .filter((m) => m.recognises(json))
  .sort((a, b) => a.fileRank - b.fileRank)[0];
