import sys
import dymesh

# world mode: a scenario file, run to the end
run = dymesh.load_scenario(sys.argv[1]).run()
car = run.bodies[0]
print(run.status, car.name, "delta-V", car.delta_v, "max crush [m]", car.crush.max())
print(run.summary["overall"]["energy_balance_error"])

# force-provider mode: the host integrates, the engine gives the loads at each CG
host = dymesh.load_scenario(sys.argv[1])
states = host.states()                       # (n, 12): x y z roll pitch yaw vx vy vz p q r
for _ in range(200):
    loads = host.host_step(states, 0.0005)   # (n, 9): force, moment (body), force (earth)
    states[0, 6:8] += loads[0, 6:8] / host.bodies[0].mass * 0.0005
    states[0, 0:2] += states[0, 6:8] * 0.0005
host.host_finish(states)
print(host.summary["overall"]["status"], host.bodies[0].vertices.shape)
