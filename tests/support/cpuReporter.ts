// A Playwright reporter that says where the browser tests' CPU goes: the whole machine's busy
// time (/proc/stat, every process counted: the browsers' renderer and GPU processes are not the
// runner's children) sampled twice a second and shared out equally among the tests running in
// each interval. Written, most costly first, to build/test-logs/e2e-cpu.tsv (CPU s, wall s,
// test); a run beside other work (npm test's unit lane) charges that work to the tests too, so
// compare runs of the browser tests alone (`npx playwright test`). Linux only; elsewhere silent.
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import type { Reporter, TestCase } from '@playwright/test/reporter';

const ticksPerSecond = 100; // USER_HZ on Linux

function machineBusyTicks(): number | null {
  if (!existsSync('/proc/stat')) return null;
  const f = readFileSync('/proc/stat', 'utf8').split('\n')[0].trim().split(/\s+/).slice(1);
  const [user, nice, system, , , irq, softirq, steal] = f.map(Number);
  return user + nice + system + irq + softirq + steal;
}

export default class CpuReporter implements Reporter {
  private running = new Map<TestCase, { cpu: number; started: number }>();
  private done: Array<{ title: string; cpu: number; wall: number }> = [];
  private last = machineBusyTicks();
  private timer: ReturnType<typeof setInterval> | null = null;

  onBegin(): void {
    if (this.last === null) return;
    this.timer = setInterval(() => this.sample(), 500);
    this.timer.unref?.();
  }

  private sample(): void {
    const now = machineBusyTicks();
    if (now === null || this.last === null) return;
    const share = (now - this.last) / ticksPerSecond / Math.max(1, this.running.size);
    this.last = now;
    for (const t of this.running.values()) t.cpu += share;
  }

  onTestBegin(test: TestCase): void {
    this.sample();
    this.running.set(test, { cpu: 0, started: Date.now() });
  }

  onTestEnd(test: TestCase): void {
    this.sample();
    const t = this.running.get(test);
    this.running.delete(test);
    if (!t) return;
    const file = test.location.file.replace(/^.*tests\/e2e\//, '');
    this.done.push({
      title: `${file}:${test.location.line} ${test.title}`,
      cpu: t.cpu,
      wall: (Date.now() - t.started) / 1000,
    });
  }

  onEnd(): void {
    if (this.timer) clearInterval(this.timer);
    if (this.last === null || this.done.length === 0) return;
    this.done.sort((a, b) => b.cpu - a.cpu);
    const total = this.done.reduce((s, d) => s + d.cpu, 0);
    const lines = [
      `# browser tests' CPU (machine busy time shared among the tests running): ${total.toFixed(0)} s in all`,
      'cpu_s\twall_s\ttest',
      ...this.done.map((d) => `${d.cpu.toFixed(1)}\t${d.wall.toFixed(1)}\t${d.title}`),
    ];
    mkdirSync('build/test-logs', { recursive: true });
    writeFileSync('build/test-logs/e2e-cpu.tsv', `${lines.join('\n')}\n`);
  }
}
