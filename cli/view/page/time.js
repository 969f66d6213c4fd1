// time.js - the sequence controls of the viewer's header: the frame box runs one frame of
// the scene's camera path (POST /api/frame, docs/viewer-api.md), `play` runs frame after
// frame (each follows on from the one before, so temporal nodes keep their history) until
// pressed again. At most one frame is in flight; the next is sent when its answer is drawn.
'use strict';

const timeState = {playing: false};

async function onFrameAnswer(body, resp) {
  await onRunAnswer(body, resp);
  if (!resp.ok) timeState.playing = false;
  $('frame-box').value = S.state ? S.state.frame : $('frame-box').value;
  $('play-btn').textContent = timeState.playing ? 'stop' : 'play';
  if (timeState.playing) setTimeout(() => sendFrame(S.state.frame + 1), 0);
}
const frameSender = new LatestSender('/api/frame', onFrameAnswer);

function sendFrame(n) {
  frameSender.send('frame', `frame=${Math.max(0, Math.floor(n))}`);
}

$('frame-box').addEventListener('change', () => sendFrame(Number($('frame-box').value)));
$('play-btn').addEventListener('click', () => {
  timeState.playing = !timeState.playing;
  $('play-btn').textContent = timeState.playing ? 'stop' : 'play';
  if (timeState.playing) sendFrame((S.state ? S.state.frame : 0) + 1);
});
