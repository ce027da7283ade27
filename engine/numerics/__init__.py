"""The numerical kit the simulations share: compiled RK4 steps, event location, step budgets."""
