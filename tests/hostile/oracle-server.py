# oracle-server.py PORT - the server of the "oracle" submission (tools/hostile.sh):
# for each connection, one line of 15 hexadecimal floats (k_d, the point, n,
# the light's position and intensity) gets back lambert's three channels,
# L = k_d I max(0, n . l) / r^2.  It stands for a student's own server that
# runs the hand-out's compiled reference.
import math
import socket
import sys

server = socket.socket()
server.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
server.bind(("127.0.0.1", int(sys.argv[1])))
server.listen(64)
while True:
    client, _ = server.accept()
    with client, client.makefile("rw") as f:
        v = [float.fromhex(x) for x in f.readline().split()]
        if len(v) != 15:
            continue
        k_d, p, n, pos, intensity = v[0:3], v[3:6], v[6:9], v[9:12], v[12:15]
        d = [pos[k] - p[k] for k in range(3)]
        r2 = sum(x * x for x in d)
        if r2 == 0:
            continue
        cos = max(0.0, sum(n[k] * d[k] for k in range(3)) / math.sqrt(r2))
        f.write(" ".join(float.hex(k_d[k] * intensity[k] * cos / r2) for k in range(3)) + "\n")
