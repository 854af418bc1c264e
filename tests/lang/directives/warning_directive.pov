#warning "careful"
sphere { 0, 1 }
// warning: 1:1 careful
