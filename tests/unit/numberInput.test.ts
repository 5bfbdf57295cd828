// The panels' number inputs: a committed entry is clamped to the range and rounded to the places
// shown, and whenever that is not the number typed the status line is told why, in one sentence
// naming the input, what was typed, the limit and the value set.
import { describe, expect, it } from 'vitest';
import { gridForPreset } from '../../web/model/grid';
import { segmentsForLength } from '../../web/model/lengthen';
import { DEFAULT_GROWTH } from '../../web/model/session';
import {
  growthForStrands,
  LENGTH_RANGE_CM,
  STRANDS_RANGE,
  strandsOf,
} from '../../web/ui/detailPanel';
import { commitNumber, formatValue } from '../../web/ui/numberInput';

const length = { label: 'Max length', unit: 'cm', decimals: 3 };

describe('commitNumber', () => {
  it('keeps a number in range as typed, with nothing to say', () => {
    expect(commitNumber(LENGTH_RANGE_CM, '60', length)).toEqual({ value: 60, message: '' });
    expect(commitNumber(LENGTH_RANGE_CM, '100', length)).toEqual({ value: 100, message: '' });
    expect(commitNumber(LENGTH_RANGE_CM, ' 2.5 ', length)).toEqual({ value: 2.5, message: '' });
  });

  it('says why a number above the maximum is set to it', () => {
    expect(commitNumber(LENGTH_RANGE_CM, '120', length)).toEqual({
      value: 100,
      message: 'Max length: 120 cm is above the maximum 100 cm; set to 100 cm.',
    });
  });

  it('says why a number below the minimum is set to it', () => {
    expect(commitNumber(LENGTH_RANGE_CM, '0.5', length)).toEqual({
      value: 2,
      message: 'Max length: 0.5 cm is below the minimum 2 cm; set to 2 cm.',
    });
    expect(commitNumber(STRANDS_RANGE, '-5', { label: 'Strands', decimals: 0 })?.message).toBe(
      'Strands: -5 is below the minimum 1,000; set to 1,000.',
    );
  });

  it('says why a number with more places than shown is rounded', () => {
    expect(commitNumber(LENGTH_RANGE_CM, '60.12345', length)).toEqual({
      value: 60.123,
      message: 'Max length: 60.12345 cm has more than 3 decimal places; set to 60.123 cm.',
    });
    expect(commitNumber(STRANDS_RANGE, '12345.6', { label: 'Strands', decimals: 0 })?.message).toBe(
      'Strands: 12345.6 is not a whole number; set to 12,346.',
    );
    // degrees are written without a space
    expect(
      commitNumber({ min: -30, max: 30, step: 0.5 }, '45', { label: 'Yaw', unit: '°', decimals: 2 })
        ?.message,
    ).toBe('Yaw: 45° is above the maximum 30°; set to 30°.');
  });

  it('changes nothing for an empty or non-numeric entry', () => {
    expect(commitNumber(LENGTH_RANGE_CM, '', length)).toBeNull();
    expect(commitNumber(LENGTH_RANGE_CM, '  ', length)).toBeNull();
    expect(commitNumber(LENGTH_RANGE_CM, 'abc', length)).toBeNull();
    expect(commitNumber(LENGTH_RANGE_CM, 'Infinity', length)).toBeNull();
  });

  it('formats values with thousands and at most the places shown', () => {
    expect(formatValue(100000, { label: 'Strands', decimals: 0 })).toBe('100,000');
    expect(formatValue(0.1235, { label: 'Curl radius' })).toBe('0.1235');
    expect(formatValue(5, { label: 'Brush radius', unit: 'mm', decimals: 2 })).toBe('5 mm');
  });
});

describe('the Hair panel ranges', () => {
  it('lets the maximum length reach 100 cm', () => {
    expect(LENGTH_RANGE_CM.max).toBe(100);
  });

  it('shows the strand count typed (sampling gives at least that many, the cap the rest)', () => {
    for (const n of [1000, 12_000, 30_000, 45_000, 100_000]) {
      const g = { ...DEFAULT_GROWTH, ...growthForStrands(n) };
      expect(strandsOf(g)).toBe(n);
      expect(strandsOf({ ...g, maxStrands: 0 })).toBeGreaterThanOrEqual(n);
    }
  });

  it('gives a strand of the maximum length enough growth steps on the session grid', () => {
    const step = gridForPreset('25k').step;
    // the default 32 cm keeps the default cap; 60 cm and 100 cm get twice their steps
    expect(segmentsForLength(3.2, 0.5, step)).toBe(DEFAULT_GROWTH.maxSegments);
    const s60 = segmentsForLength(6, 0.5, step);
    expect(s60 * 0.5 * step).toBeGreaterThanOrEqual(2 * 6);
    expect((s60 - 1) * 0.5 * step).toBeLessThan(2 * 6);
    const fine = gridForPreset('250k').step;
    expect(segmentsForLength(10, 0.5, fine)).toBeGreaterThan(segmentsForLength(10, 0.5, step));
    // never past the session limit
    expect(segmentsForLength(10, 0.05, fine)).toBe(2000);
  });
});
