box { 0, 1
  scale <1, 0, 1>
}
// error: 2:9 a scale of <1, 0, 1> has a zero component
