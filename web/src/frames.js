// The latest image of each pipeline, and a timeline to step back through the frames or play them.
import { number } from './format.js';

export class Frames {
  constructor(container, slider, label, playButton) {
    this.container = container;
    this.slider = slider;
    this.label = label;
    this.playButton = playButton;
    this.frames = [];
    this.index = -1;
    this.timer = null;
    slider.addEventListener('input', () => this.show(Number(slider.value)));
    playButton.addEventListener('click', () => (this.timer ? this.stop() : this.play()));
  }

  // A new frame: shown at once when the timeline is at its end (following the run).
  add(frame) {
    const following = this.index === this.frames.length - 1;
    this.frames.push(frame);
    this.slider.max = String(this.frames.length - 1);
    if (following && !this.timer) this.show(this.frames.length - 1);
  }

  show(index) {
    if (index < 0 || index >= this.frames.length) return;
    this.index = index;
    this.slider.value = String(index);
    const f = this.frames[index];
    this.label.textContent = `frame ${f.frame} · step ${f.step} · t = ${number(f.time)} s`;
    const figures = [];
    const existing = new Map([...this.container.querySelectorAll('figure')].map((el) => [el.dataset.key, el]));
    for (const img of f.images) {
      const key = `${img.pipeline}/${img.view}`;
      let fig = existing.get(key);
      if (!fig) {
        fig = document.createElement('figure');
        fig.dataset.key = key;
        fig.innerHTML = '<img alt=""><figcaption></figcaption>';
        fig.querySelector('figcaption').textContent = `${img.pipeline} · ${img.view}`;
      }
      const el = fig.querySelector('img');
      if (el.getAttribute('src') !== img.url) el.src = img.url;
      el.alt = `${img.pipeline} ${img.view} frame ${f.frame}`;
      figures.push(fig);
    }
    this.container.replaceChildren(...figures);
  }

  play() {
    if (this.frames.length < 2) return;
    this.playButton.textContent = 'Pause';
    if (this.index >= this.frames.length - 1) this.show(0);
    this.timer = setInterval(() => {
      if (this.index >= this.frames.length - 1) return this.stop();
      this.show(this.index + 1);
    }, 400);
  }

  stop() {
    clearInterval(this.timer);
    this.timer = null;
    this.playButton.textContent = 'Play';
  }
}
