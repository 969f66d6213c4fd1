// time.js - the sequence controls of the viewer's header: the frame box runs one frame of
// the scene's camera path (POST /api/frame, docs/viewer-api.md), `play` runs frame after
// frame (each follows on from the one before, so temporal nodes keep their history) until
// pressed again. At most one frame is in flight; the next is sent when its answer is drawn.
import { LatestSender } from './net.js';
import { state } from './state.js';
import { $ } from './ui.js';

let playing = false;
let frameSender = null;

function sendFrame(n) {
  frameSender.send('frame', `frame=${Math.max(0, Math.floor(n))}`);
}

// onRunAnswer(body, resp): what app.js does with the answer to a run request.
export function wireTime(onRunAnswer) {
  frameSender = new LatestSender('/api/frame', async (body, resp) => {
    await onRunAnswer(body, resp);
    if (!resp.ok) playing = false;
    if (state.server) $('frame-box').value = state.server.frame;
    $('play-btn').textContent = playing ? 'stop' : 'play';
    if (playing) setTimeout(() => sendFrame(state.server.frame + 1), 0);
  });
  $('frame-box').addEventListener('change', () => sendFrame(Number($('frame-box').value)));
  $('play-btn').addEventListener('click', () => {
    playing = !playing;
    $('play-btn').textContent = playing ? 'stop' : 'play';
    if (playing) sendFrame((state.server ? state.server.frame : 0) + 1);
  });
}
