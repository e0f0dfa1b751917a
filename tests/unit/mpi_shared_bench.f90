!> Benchmark (make bench, scripts/bench_shared_sum.sh): the fixed-order shared-node sum
!> (par_shared_sum) against the plain sum of per-rank partials (par_shared_sum_plain), on a
!> METIS partition of an nx*ny*nz hex box, 3 force components per node. Each timed step is
!> what one explicit cycle would do after the element kernels: scatter the 8 corner forces of
!> every element (into f, or into the contribution slots at shared nodes) and exchange.
!> The two variants alternate in rounds; rank 0 prints the slowest rank's time per step.
!> A barrier before each exchange keeps the waiting for slower ranks out of the exchange
!> time (and inside the step time).
!> Usage: mpi_shared_bench [nx ny nz [steps]]
program mpi_shared_bench
   use, intrinsic :: iso_fortran_env, only: output_unit
   use dx_kinds, only: wp, nv_chunk
   use dx_error, only: error_t
   use dx_par, only: par_init, par_finalize, par_rank, par_size, par_allreduce, par_wtime, &
                     par_barrier, PAR_MAX, PAR_SUM
   use dx_par_plan, only: shared_sum_t, par_shared_setup, par_shared_sum, par_shared_sum_plain
   use dx_partition, only: partition_t, partition_elements
   implicit none
   type(error_t), allocatable :: error
   type(partition_t) :: part
   type(shared_sum_t) :: plan
   integer :: nx, ny, nz, steps, np, me, ne, nn, e, k, i, j, l, n, nsh, nc, round, q, s
   integer, allocatable :: conn(:, :), ewgt(:), mine(:), snum(:), nbr(:), nbr_ptr(:), &
                           nbr_snode(:), c_node(:), c_key(:), slot(:, :), gp(:), ge(:)
   real(wp), allocatable :: fe(:, :, :), f(:, :), cval(:, :), res(:, :), partial(:, :)
   integer, allocatable :: tgt(:, :), sk(:), sl(:), shared_nodes(:)
   real(wp) :: t0, t_fixed, t_plain, tmp, x_fixed, x_plain
   character(32) :: arg
   integer :: stats(3)

   call par_init(error)
   if (allocated(error)) error stop 2
   np = par_size(); me = par_rank()
   nx = 50; ny = 50; nz = 40; steps = 200
   if (command_argument_count() >= 3) then
      call get_command_argument(1, arg); read(arg, *) nx
      call get_command_argument(2, arg); read(arg, *) ny
      call get_command_argument(3, arg); read(arg, *) nz
   end if
   if (command_argument_count() >= 4) then
      call get_command_argument(4, arg); read(arg, *) steps
   end if
   ne = nx*ny*nz
   nn = (nx + 1)*(ny + 1)*(nz + 1)
   allocate(conn(8, ne), ewgt(ne))
   e = 0
   do k = 0, nz - 1
      do j = 0, ny - 1
         do i = 0, nx - 1
            e = e + 1
            conn(:, e) = [id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), &
               id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)]
         end do
      end do
   end do
   ewgt = 1
   gp = [1]
   allocate(ge(0))
   call partition_elements(conn, nn, ewgt, gp, ge, np, part, error)
   if (allocated(error)) error stop 3
   mine = pack([(e, e = 1, ne)], part%epart == me)
   ! shared numbering and neighbour lists from the partition (as the rank file holds them)
   allocate(snum(nn))
   snum = 0
   nsh = 0
   do n = 1, nn
      if (part%nr_ptr(n + 1) - part%nr_ptr(n) > 1 .and. &
          any(part%nr_rank(part%nr_ptr(n):part%nr_ptr(n + 1) - 1) == me)) then
         nsh = nsh + 1
         snum(n) = nsh
      end if
   end do
   nbr = [integer ::]; nbr_snode = [integer ::]; nbr_ptr = [1]
   do q = 0, np - 1
      if (q == me) cycle
      l = 0
      do n = 1, nn
         if (snum(n) > 0) then
            if (any(part%nr_rank(part%nr_ptr(n):part%nr_ptr(n + 1) - 1) == q)) then
               nbr_snode = [nbr_snode, snum(n)]
               l = l + 1
            end if
         end if
      end do
      if (l > 0) then
         nbr = [nbr, q]
         nbr_ptr = [nbr_ptr, nbr_ptr(size(nbr_ptr)) + l]
      end if
   end do
   ! contribution slots: (corner, element) at a shared node -> slot number; key as in the
   ! serial scatter: ((block - 1)*8 + corner - 1)*nv_chunk + position in block
   allocate(slot(8, size(mine)), c_node(8*size(mine)), c_key(8*size(mine)))
   slot = 0
   nc = 0
   do l = 1, size(mine)
      e = mine(l)
      do k = 1, 8
         if (snum(conn(k, e)) > 0) then
            nc = nc + 1
            slot(k, l) = nc
            c_node(nc) = snum(conn(k, e))
            c_key(nc) = (((e - 1)/nv_chunk)*8 + k - 1)*nv_chunk + mod(e - 1, nv_chunk) + 1
         end if
      end do
   end do
   call par_shared_setup(plan, nsh, nbr, nbr_ptr, nbr_snode, c_node(1:nc), c_key(1:nc))
   allocate(fe(3, 8, size(mine)), f(3, nn), cval(3, nc), res(3, nsh), partial(3, nsh))
   do l = 1, size(mine)
      do k = 1, 8
         fe(:, k, l) = [real(k, wp), real(l, wp)*1.0e-3_wp, 1.0_wp/real(k + l, wp)]
      end do
   end do
   ! scatter targets: a shared corner goes to the sink node nn + 1 (fixed-order variant);
   ! (sk, sl, slot) lists the shared corners whose values are copied to the slots
   allocate(tgt(8, size(mine)), sk(nc), sl(nc))
   do l = 1, size(mine)
      do k = 1, 8
         tgt(k, l) = conn(k, mine(l))
         if (slot(k, l) > 0) then
            tgt(k, l) = nn + 1
            sk(slot(k, l)) = k
            sl(slot(k, l)) = l
         end if
      end do
   end do
   shared_nodes = pack([(n, n = 1, nn)], snum > 0)
   deallocate(f)
   allocate(f(3, nn + 1))
   t_fixed = 0.0_wp; t_plain = 0.0_wp; x_fixed = 0.0_wp; x_plain = 0.0_wp
   do round = 1, 10
      t0 = par_wtime()
      do s = 1, steps/10
         f = 0.0_wp
         do k = 1, 8
            do l = 1, size(mine)
               f(:, tgt(k, l)) = f(:, tgt(k, l)) - fe(:, k, l)
            end do
         end do
         do i = 1, nc
            cval(:, i) = -fe(:, sk(i), sl(i))
         end do
         call par_barrier()
         tmp = par_wtime()
         call par_shared_sum(plan, cval(:, 1:nc), res)
         x_fixed = x_fixed + par_wtime() - tmp
      end do
      t_fixed = t_fixed + par_wtime() - t0
      t0 = par_wtime()
      do s = 1, steps/10
         f = 0.0_wp
         do k = 1, 8
            do l = 1, size(mine)
               f(:, conn(k, mine(l))) = f(:, conn(k, mine(l))) - fe(:, k, l)
            end do
         end do
         call par_barrier()
         tmp = par_wtime()
         partial = f(:, shared_nodes)
         call par_shared_sum_plain(plan, partial, res)
         x_plain = x_plain + par_wtime() - tmp
      end do
      t_plain = t_plain + par_wtime() - t0
   end do
   t_fixed = t_fixed/real(10*(steps/10), wp)
   t_plain = t_plain/real(10*(steps/10), wp)
   x_fixed = x_fixed/real(10*(steps/10), wp)
   x_plain = x_plain/real(10*(steps/10), wp)
   call par_allreduce(t_fixed, PAR_MAX)
   call par_allreduce(t_plain, PAR_MAX)
   call par_allreduce(x_fixed, PAR_MAX)
   call par_allreduce(x_plain, PAR_MAX)
   stats = [nsh, nc, size(plan%ord_src) - nc]
   call par_allreduce(stats, PAR_MAX)
   tmp = real(nsh, wp)
   call par_allreduce(tmp, PAR_SUM)
   if (me == 0) then
      write(output_unit, '(a,i0,a,i0,a,i0,a,i0,a,i0,a,i0,a,i0)') 'np ', np, ' elements ', ne, &
         ' shared-node entries (sum over ranks) ', nint(tmp), ' max per rank ', stats(1), &
         ' contributions kept apart (max) ', stats(2), ' received (max) ', stats(3), &
         ' steps ', 10*(steps/10)
      write(output_unit, '(a,es10.3,a,es10.3,a,f6.3)') 'scatter+exchange [s/step]: fixed-order ', &
         t_fixed, '  plain ', t_plain, '  ratio ', t_fixed/t_plain
      write(output_unit, '(a,es10.3,a,es10.3,a,f6.3)') 'exchange alone   [s/step]: fixed-order ', &
         x_fixed, '  plain ', x_plain, '  ratio ', x_fixed/x_plain
   end if
   call par_finalize()

contains

   pure integer function id(a, b, c)
      integer, intent(in) :: a, b, c
      id = 1 + a + (nx + 1)*(b + (ny + 1)*c)
   end function id
end program mpi_shared_bench
