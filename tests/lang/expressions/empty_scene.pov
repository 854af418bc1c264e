// nothing
/* nested /* comment */ still */
// model: objects.len = 0
// model: version = 3.7
// model: background = { rgb: <0, 0, 0>, filter: 0, transmit: 0 }
