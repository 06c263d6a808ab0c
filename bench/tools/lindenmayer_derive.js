// The fractal plant (ABOP 1.24f) derived in memory by the npm `lindenmayer` library, the same
// string `sprout expand fractal_plant -n N` prints: the baseline of bench/expand_bench.sh.
// Prints the string's length so that the work cannot be skipped.
const LSystem = require('lindenmayer');
const n = parseInt(process.argv[2] || '11', 10);
const plant = new LSystem({
  axiom: 'X',
  productions: { X: 'F-[[X]+X]+F[+FX]-X', F: 'FF' },
});
const s = plant.iterate(n);
console.log(s.length);
